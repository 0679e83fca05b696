/* hslam nav: CRangeFusion / CPolarProfile (see CRangeFusion.h). */
#include <hslam/nav/CRangeFusion.h>
#include <hslam/common/range_data.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
CPolarProfile::CPolarProfile(double bin_rad, double maxRange_m)
	: m_bin(bin_rad), m_maxRange(maxRange_m), m_ranges(static_cast<size_t>(std::ceil(2.0 * M_PI / bin_rad)), maxRange_m)
{
	m_cos.resize(m_ranges.size());
	m_sin.resize(m_ranges.size());
	for (size_t i = 0; i < m_ranges.size(); ++i) m_cos[i] = std::cos(binAngle(i)), m_sin[i] = std::sin(binAngle(i));
}

void CPolarProfile::clear() { std::fill(m_ranges.begin(), m_ranges.end(), m_maxRange); }

size_t CPolarProfile::binOf(double angle) const
{
	// Angles come in (-pi, pi] or [0, 2 pi) almost always: no fmod then.
	const double a = angle >= 0 && angle < 2 * M_PI ? angle
					 : angle < 0 && angle >= -2 * M_PI ? angle + 2 * M_PI
													   : mrpt::math::wrapTo2Pi(angle);
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
	// A bin's nearest point blocks the corridor if its lateral offset from the
	// corridor axis is below halfWidth and it lies ahead (bin points from the
	// cached cos/sin: no trigonometry per bin).
	const double c = std::cos(heading), s = std::sin(heading), hw2 = halfWidth * halfWidth;
	double free = m_maxRange;
	for (size_t i = 0; i < m_ranges.size(); ++i)
	{
		if (m_ranges[i] >= m_maxRange) continue;
		const double x = pointX(i), y = pointY(i);
		const double along = x * c + y * s, lateral = y * c - x * s;
		if (along > 0 && lateral * lateral < hw2) free = std::min(free, along - std::sqrt(hw2 - lateral * lateral));
	}
	return std::max(0.0, free);
}

void CPolarProfile::corridorFreeDistances(double step, int n, double halfWidth, std::vector<double>& free) const
{
	free.assign(2 * n + 1, m_maxRange);
	if (step != m_gridStep || n != m_gridN)
	{
		m_gridStep = step, m_gridN = n;
		m_gridCos.resize(2 * n + 1), m_gridSin.resize(2 * n + 1);
		for (int k = -n; k <= n; ++k) m_gridCos[k + n] = std::cos(k * step), m_gridSin[k + n] = std::sin(k * step);
	}
	const double turns = 2 * M_PI / step;
	const int turn = static_cast<int>(std::lround(turns));
	const bool periodic = std::abs(turns - turn) < 1e-9;
	const double hw2 = halfWidth * halfWidth;
	auto visit = [&](int k, double x, double y)
	{
		if (k < -n || k > n) return;
		const double along = x * m_gridCos[k + n] + y * m_gridSin[k + n];
		const double lateral = y * m_gridCos[k + n] - x * m_gridSin[k + n];
		if (along > 0 && lateral * lateral < hw2)
			free[k + n] = std::min(free[k + n], std::max(0.0, along - std::sqrt(hw2 - lateral * lateral)));
	};
	for (size_t i = 0; i < m_ranges.size(); ++i)
	{
		const double r = m_ranges[i];
		if (r >= m_maxRange) continue;
		const double x = pointX(i), y = pointY(i);
		if (!periodic)  // the grid does not close on itself: every heading
		{
			for (int k = -n; k <= n; ++k) visit(k, x, y);
			continue;
		}
		// Only headings within asin(halfWidth / r) of the point's bearing can
		// have it ahead and nearer than halfWidth to the axis.
		const double a = binAngle(i), window = r > halfWidth ? std::asin(halfWidth / r) : 0.5 * M_PI;
		const int k0 = static_cast<int>(std::floor((a - window) / step));
		const int k1 = static_cast<int>(std::ceil((a + window) / step));
		for (int k = k0; k <= k1; ++k)
		{
			visit(k, x, y);  // the same direction one turn either way, if on the grid
			if (k - turn >= -n) visit(k - turn, x, y);
			if (k + turn <= n) visit(k + turn, x, y);
		}
	}
}

CPolarProfile CRangeFusion::fuse(const mrpt::obs::CObservation2DRangeScan* scan,
								 const mrpt::obs::CObservationRange* sonar)
{
	auto p = makeProfile();
	fuseInto(p, scan, sonar);
	return p;
}

bool CRangeFusion::laserExplains(const mrpt::obs::CObservationRange::TMeasurement& m) const
{
	const auto& sp = m.sensorPose;
	const double cx = std::cos(sp.yaw), cy = std::sin(sp.yaw), cosHalf = std::cos(0.5 * m_opts.sonar_cone_rad);
	const double reach = m.sensedDistance + 1e-3 * m_opts.explained_tolerance_mm, reach2 = reach * reach;
	for (size_t k = 0; k < m_laserX.size(); ++k)
	{
		const double dx = m_laserX[k] - sp.x, dy = m_laserY[k] - sp.y, d2 = dx * dx + dy * dy;
		if (d2 > reach2) continue;
		const double along = dx * cx + dy * cy;  // inside the cone: along >= |d| cos(half)
		if (along > 0 && along * along >= d2 * cosHalf * cosHalf) return true;
	}
	return false;
}

void CRangeFusion::fuseInto(CPolarProfile& p, const mrpt::obs::CObservation2DRangeScan* scan,
							const mrpt::obs::CObservationRange* sonar)
{
	p.clear();
	m_laserX.clear(), m_laserY.clear();
	if (scan && m_opts.use_laser)
	{
		const common::TScanMount mount = common::scanMount(scan->sensorPose);
		const size_t n = scan->getScanSize();
		if (n != m_beamCount || scan->aperture != m_beamAperture || scan->rightToLeft != m_beamRightToLeft)
		{
			m_beamCount = n, m_beamAperture = scan->aperture, m_beamRightToLeft = scan->rightToLeft;
			m_beamCos.resize(n), m_beamSin.resize(n);
			for (size_t i = 0; i < n; ++i)
			{
				const double a = scan->getScanAngle(i);
				m_beamCos[i] = std::cos(a), m_beamSin[i] = std::sin(a);
			}
		}
		const double cy = std::cos(mount.yaw_rad), sy = std::sin(mount.yaw_rad);
		for (size_t i = 0; i < n; ++i)
		{
			if (!scan->getScanRangeValidity(i)) continue;
			const double r = scan->getScanRange(i);
			const double lx = r * m_beamCos[i], ly = mount.sineSign() * r * m_beamSin[i];
			const double x = mount.x_m + cy * lx - sy * ly, y = mount.y_m + sy * lx + cy * ly;
			p.addPoint(std::atan2(y, x), std::sqrt(x * x + y * y));
			m_laserX.push_back(x), m_laserY.push_back(y);
		}
	}
	if (sonar && m_opts.use_sonar)
	{
		const bool dropExplained = m_opts.drop_explained_sonar && !m_laserX.empty();
		for (const auto& m : sonar->sensedData)
		{
			if (!(m.sensedDistance > 0) || m.sensedDistance >= sonar->maxSensorDistance - 1e-3) continue;
			if (dropExplained && laserExplains(m)) continue;
			const auto& sp = m.sensorPose;
			const double half = 0.5 * m_opts.sonar_cone_rad;
			for (double a = -half; a <= half + 1e-9; a += 0.5 * m_opts.bin_rad)
			{
				const double x = sp.x + m.sensedDistance * std::cos(sp.yaw + a);
				const double y = sp.y + m.sensedDistance * std::sin(sp.yaw + a);
				p.addPoint(std::atan2(y, x), std::sqrt(x * x + y * y));
			}
		}
	}
}

}  // namespace hslam::nav
