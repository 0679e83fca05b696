/* hslam sim: CSonarSimulator (thesis 4.3; specular model described in the header). */
#include <hslam/sim/CSonarSimulator.h>

#include <algorithm>
#include <cmath>

namespace hslam::sim
{
using mrpt::math::TPoint2D;

std::vector<TSonarMount> p3dxFrontSonarRing()
{
	const double table[8][3] = {{69, 136, 90},	 {114, 119, 50},   {148, 78, 30},	{166, 27, 10},
								{166, -27, -10}, {148, -78, -30}, {114, -119, -50}, {69, -136, -90}};
	std::vector<TSonarMount> ring;
	for (const auto& t : table) ring.push_back(TSonarMount{t[0] * 1e-3, t[1] * 1e-3, t[2] * M_PI / 180.0});
	return ring;
}

std::vector<TSonarMount> p3dxAllSonars()
{
	std::vector<TSonarMount> ring = p3dxFrontSonarRing();
	const double rear[8][3] = {{-157, -136, -90}, {-203, -119, -130}, {-237, -78, -150}, {-255, -27, -170},
							   {-255, 27, 170},	  {-237, 78, 150},	  {-203, 119, 130},	  {-157, 136, 90}};
	for (const auto& t : rear) ring.push_back(TSonarMount{t[0] * 1e-3, t[1] * 1e-3, t[2] * M_PI / 180.0});
	return ring;
}

std::vector<TSonarMount> p3dxSonarRing(const std::string& ring)
{
	return ring == "all16" ? p3dxAllSonars() : p3dxFrontSonarRing();
}

CSonarSimulator::CSonarSimulator(const TSonarOptions& options) : CSonarSimulator(options, p3dxSonarRing(options.ring))
{
}

CSonarSimulator::CSonarSimulator(const TSonarOptions& options, std::vector<TSonarMount> ring)
	: m_opts(options), m_ring(std::move(ring))
{
}

TSonarEcho CSonarSimulator::traceRay(const CWorld& world, const TPoint2D& sensor, double angle) const
{
	TSonarEcho best;
	const int maxBounces = m_opts.specular_mode == "multipath" ? m_opts.max_bounces : 0;
	const double lobe = 2.0 * m_opts.max_incidence_rad;
	TPoint2D origin = sensor;
	double dirX = std::cos(angle), dirY = std::sin(angle);
	double travelled = 0;
	for (int bounce = 0; bounce <= maxBounces; ++bounce)
	{
		const double remaining = 2.0 * m_opts.max_range_m - travelled;  // round trip budget
		if (remaining <= 0) break;
		const TRayHit hit = world.castRay(origin, std::atan2(dirY, dirX), remaining);
		if (!hit.hit) break;
		travelled += hit.range_m;
		// Mirror direction at the hit.
		const double dn = dirX * hit.normal.x + dirY * hit.normal.y;
		const double rX = dirX - 2 * dn * hit.normal.x, rY = dirY - 2 * dn * hit.normal.y;
		const double backX = sensor.x - hit.point.x, backY = sensor.y - hit.point.y;
		const double back = std::hypot(backX, backY);
		const double cosToSensor = back > 1e-9 ? (rX * backX + rY * backY) / back : 1.0;
		if (std::acos(std::clamp(cosToSensor, -1.0, 1.0)) <= lobe + 1e-12)
		{
			const double range = 0.5 * (travelled + back);
			if (range <= m_opts.max_range_m)
			{
				best.echo = true;
				best.range_m = range;
				best.bounces = bounce;
				best.tag = hit.tag;
			}
			break;
		}
		origin = TPoint2D{hit.point.x + 1e-6 * rX, hit.point.y + 1e-6 * rY};
		dirX = rX;
		dirY = rY;
	}
	if (!best.echo) best.range_m = m_opts.max_range_m;
	return best;
}

TSonarEcho CSonarSimulator::echo(const CWorld& world, const mrpt::math::TPose2D& sensorPose) const
{
	const int steps = std::max(1, static_cast<int>(std::ceil(m_opts.cone_rad / m_opts.ray_step_rad)));
	TSonarEcho first;
	first.range_m = m_opts.max_range_m;
	const TPoint2D origin{sensorPose.x, sensorPose.y};
	for (int k = 0; k <= steps; ++k)
	{
		const double a = sensorPose.phi - 0.5 * m_opts.cone_rad + m_opts.cone_rad * k / steps;
		const TSonarEcho e = traceRay(world, origin, a);
		if (e.echo && (!first.echo || e.range_m < first.range_m)) first = e;
	}
	return first;
}

void CSonarSimulator::simulate(const CWorld& worldModel, const mrpt::math::TPose2D& robot, std::mt19937_64& rng,
							   mrpt::obs::CObservationRange& obs, std::vector<TSonarEcho>* echoes) const
{
	obs.sensorLabel = m_opts.label;
	obs.minSensorDistance = static_cast<float>(m_opts.min_range_m);
	obs.maxSensorDistance = static_cast<float>(m_opts.max_range_m);
	obs.sensorConeApperture = static_cast<float>(m_opts.cone_rad);
	obs.sensedData.clear();
	if (echoes) echoes->clear();
	std::normal_distribution<double> gauss(0.0, 1.0);
	const double c = std::cos(robot.phi), s = std::sin(robot.phi);
	for (size_t k = 0; k < m_ring.size(); ++k)
	{
		const TSonarMount& m = m_ring[k];
		const mrpt::math::TPose2D world{robot.x + c * m.x_m - s * m.y_m, robot.y + s * m.x_m + c * m.y_m,
										robot.phi + m.yaw_rad};
		const TSonarEcho e = echo(worldModel, world);
		double r = e.range_m;
		if (e.echo)
		{
			if (m_opts.noise_std_m > 0) r += m_opts.noise_std_m * gauss(rng);
			r = std::clamp(r, m_opts.min_range_m, m_opts.max_range_m);
		}
		mrpt::obs::CObservationRange::TMeasurement meas;
		meas.sensorID = static_cast<uint16_t>(k);
		meas.sensorPose = mrpt::math::TPose3D(m.x_m, m.y_m, m_opts.z_m, m.yaw_rad, 0, 0);
		meas.sensedDistance = static_cast<float>(r);
		obs.sensedData.push_back(meas);
		if (echoes) echoes->push_back(e);
	}
}

}  // namespace hslam::sim
