/* hslam sim: CLaserSimulator. */
#include <hslam/sim/CLaserSimulator.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
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
	std::vector<double> range_m(m_beams);
	std::vector<char> valid(m_beams);
	for (size_t i = 0; i < m_beams; ++i)
	{
		const double along = m_opts.upside_down ? -beamAngle(i) : beamAngle(i);  // seen from above
		const TRayHit hit = world.castRay(origin, heading + along, m_maxRange);
		range_m[i] = hit.range_m, valid[i] = hit.hit;
		if (beamTags && hit.hit) (*beamTags)[i] = hit.tag;
	}
	addArtefacts(range_m, valid, rng);
	for (size_t i = 0; i < m_beams; ++i)
	{
		double r = range_m[i];
		bool ok = valid[i] != 0;
		if (ok)
		{
			if (m_opts.noise_std_m > 0) r += m_opts.noise_std_m * gauss(rng);
			if (m_opts.range_resolution_m > 0) r = std::round(r / m_opts.range_resolution_m) * m_opts.range_resolution_m;
			r = std::max(r, 0.0);
			if (r >= m_maxRange) ok = false;
		}
		if (!ok) r = m_maxRange;
		scan.setScanRange(i, static_cast<float>(r));
		scan.setScanRangeValidity(i, ok);
	}
}

void CLaserSimulator::addArtefacts(std::vector<double>& range_m, std::vector<char>& valid, std::mt19937_64& rng) const
{
	std::uniform_real_distribution<double> uniform(0.0, 1.0);
	if (m_opts.mixed_pixel_probability > 0)
	{
		const std::vector<double> truth = range_m;
		const std::vector<char> truthValid = valid;
		for (size_t i = 0; i + 1 < truth.size(); ++i)
		{
			// a missing return is a surface at max range
			const double a = truthValid[i] ? truth[i] : m_maxRange, b = truthValid[i + 1] ? truth[i + 1] : m_maxRange;
			if (std::abs(a - b) <= m_opts.mixed_pixel_jump_m || uniform(rng) >= m_opts.mixed_pixel_probability) continue;
			const size_t edge = a < b ? i : i + 1;  // the beam on the nearer surface
			range_m[edge] = std::min(a, b) + uniform(rng) * std::abs(a - b);
			valid[edge] = range_m[edge] < m_maxRange;
		}
	}
	if (m_opts.dropout_probability <= 0 && m_opts.spurious_probability <= 0) return;
	for (size_t i = 0; i < range_m.size(); ++i)
	{
		if (!valid[i]) continue;
		if (uniform(rng) < m_opts.dropout_probability) valid[i] = 0;
		else if (uniform(rng) < m_opts.spurious_probability)
			range_m[i] = 0.1 + uniform(rng) * std::max(0.0, range_m[i] - 0.1);
	}
}

}  // namespace hslam::sim
