/* hslam nav: CRangeFusion / CPolarProfile (see CRangeFusion.h). */
#include <hslam/nav/CRangeFusion.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
CPolarProfile::CPolarProfile(double bin_rad, double maxRange_m)
	: m_bin(bin_rad), m_maxRange(maxRange_m), m_ranges(static_cast<size_t>(std::ceil(2.0 * M_PI / bin_rad)), maxRange_m)
{
}

void CPolarProfile::clear() { std::fill(m_ranges.begin(), m_ranges.end(), m_maxRange); }

size_t CPolarProfile::binOf(double angle) const
{
	const double a = mrpt::math::wrapTo2Pi(angle);
	return std::min(m_ranges.size() - 1, static_cast<size_t>(a / m_bin));
}

double CPolarProfile::binAngle(size_t i) const { return mrpt::math::wrapToPi((i + 0.5) * m_bin); }

void CPolarProfile::addPoint(double angle, double range)
{
	if (!(range >= 0)) return;
	double& r = m_ranges[binOf(angle)];
	r = std::min(r, range);
}

double CPolarProfile::minRange(double from, double to) const
{
	double best = m_maxRange;
	const int n = static_cast<int>(std::ceil((to - from) / m_bin)) + 1;
	for (int k = 0; k < n; ++k) best = std::min(best, m_ranges[binOf(std::min(to, from + k * m_bin))]);
	return best;
}

double CPolarProfile::corridorFreeDistance(double heading, double halfWidth) const
{
	// A bin's nearest point (range r at angle a) blocks the corridor if its
	// lateral offset from the corridor axis is below halfWidth and it lies ahead.
	double free = m_maxRange;
	for (size_t i = 0; i < m_ranges.size(); ++i)
	{
		if (m_ranges[i] >= m_maxRange) continue;
		const double rel = mrpt::math::wrapToPi(binAngle(i) - heading);
		const double along = m_ranges[i] * std::cos(rel), lateral = std::abs(m_ranges[i] * std::sin(rel));
		if (along > 0 && lateral < halfWidth)
			free = std::min(free, along - std::sqrt(halfWidth * halfWidth - lateral * lateral));
	}
	return std::max(0.0, free);
}

CPolarProfile CRangeFusion::fuse(const mrpt::obs::CObservation2DRangeScan* scan,
								 const mrpt::obs::CObservationRange* sonar) const
{
	CPolarProfile p(m_opts.bin_rad, m_opts.max_range_m);
	if (scan && m_opts.use_laser)
	{
		const auto& sp = scan->sensorPose;
		const size_t n = scan->getScanSize();
		const double step = n > 1 ? scan->aperture / (n - 1) : 0.0;
		for (size_t i = 0; i < n; ++i)
		{
			if (!scan->getScanRangeValidity(i)) continue;
			const double a = (scan->rightToLeft ? -0.5 * scan->aperture + i * step : 0.5 * scan->aperture - i * step);
			const double r = scan->getScanRange(i);
			const double x = sp.x() + r * std::cos(sp.yaw() + a), y = sp.y() + r * std::sin(sp.yaw() + a);
			p.addPoint(std::atan2(y, x), std::hypot(x, y));
		}
	}
	if (sonar && m_opts.use_sonar)
	{
		for (const auto& m : sonar->sensedData)
		{
			if (!(m.sensedDistance > 0) || m.sensedDistance >= sonar->maxSensorDistance - 1e-3) continue;
			const auto& sp = m.sensorPose;
			const double half = 0.5 * m_opts.sonar_cone_rad;
			for (double a = -half; a <= half + 1e-9; a += 0.5 * m_opts.bin_rad)
			{
				const double x = sp.x + m.sensedDistance * std::cos(sp.yaw + a);
				const double y = sp.y + m.sensedDistance * std::sin(sp.yaw + a);
				p.addPoint(std::atan2(y, x), std::hypot(x, y));
			}
		}
	}
	return p;
}

}  // namespace hslam::nav
