/* hslam sim: CLaserSimulator. */
#include <hslam/sim/CLaserSimulator.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace hslam::sim
{
CLaserSimulator::CLaserSimulator(const TLaserOptions& options) : m_opts(options)
{
	double res = m_opts.resolution_rad, defaultMax = 8.0;
	if (m_opts.preset == "lms200")
	{
		m_fov = M_PI;
		res = M_PI / 180.0;
	}
	else if (m_opts.preset == "lms100")
	{
		m_fov = 270.0 * M_PI / 180.0;
		res = 0.5 * M_PI / 180.0;
		defaultMax = 20.0;
	}
	else
		m_fov = m_opts.fov_rad;
	m_beams = static_cast<size_t>(std::lround(m_fov / res)) + 1;
	m_maxRange = m_opts.max_range_m > 0 ? m_opts.max_range_m : defaultMax;
}

double CLaserSimulator::beamAngle(size_t i) const
{
	return -0.5 * m_fov + m_fov * static_cast<double>(i) / static_cast<double>(m_beams - 1);
}

void CLaserSimulator::simulate(const CWorld& world, const mrpt::math::TPose2D& robot, std::mt19937_64& rng,
							   mrpt::obs::CObservation2DRangeScan& scan, std::vector<TObjectTag>* beamTags) const
{
	scan.sensorLabel = m_opts.label;
	scan.aperture = static_cast<float>(m_fov);
	scan.rightToLeft = true;
	scan.maxRange = static_cast<float>(m_maxRange);
	scan.stdError = static_cast<float>(m_opts.noise_std_m);
	scan.sensorPose = mrpt::poses::CPose3D(m_opts.x_m, m_opts.y_m, m_opts.z_m, m_opts.yaw_rad, 0, m_opts.upside_down ? M_PI : 0.0);
	scan.resizeScan(m_beams);
	if (beamTags) beamTags->assign(m_beams, TObjectTag{EObjectKind::none, -1, 0});

	const double c = std::cos(robot.phi), s = std::sin(robot.phi);
	const mrpt::math::TPoint2D origin{robot.x + c * m_opts.x_m - s * m_opts.y_m, robot.y + s * m_opts.x_m + c * m_opts.y_m};
	const double heading = robot.phi + m_opts.yaw_rad;
	std::normal_distribution<double> gauss(0.0, 1.0);
	for (size_t i = 0; i < m_beams; ++i)
	{
		const double along = m_opts.upside_down ? -beamAngle(i) : beamAngle(i);  // seen from above
		const TRayHit hit = world.castRay(origin, heading + along, m_maxRange);
		double r = hit.range_m;
		bool valid = hit.hit;
		if (valid)
		{
			if (m_opts.noise_std_m > 0) r += m_opts.noise_std_m * gauss(rng);
			if (m_opts.range_resolution_m > 0) r = std::round(r / m_opts.range_resolution_m) * m_opts.range_resolution_m;
			r = std::max(r, 0.0);
			if (r >= m_maxRange) valid = false;
		}
		if (!valid) r = m_maxRange;
		scan.setScanRange(i, static_cast<float>(r));
		scan.setScanRangeValidity(i, valid);
		if (beamTags && hit.hit) (*beamTags)[i] = hit.tag;
	}
}

}  // namespace hslam::sim
