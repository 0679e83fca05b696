#include <hslam/dynamic/CLegDetector.h>
#include <hslam/dynamic/CStaticEvidenceGrid.h>

#include <algorithm>
#include <cmath>

namespace hslam::dynamic
{
int CStaticEvidenceGrid::index(double v) const { return static_cast<int>(std::floor(v / m_options.resolution_m)); }

void CStaticEvidenceGrid::hit(int64_t key, double t_s)
{
	TCell& c = m_cells[key];
	if (c.scans > 0 && c.last_s == t_s) return;  // each cell counts once per scan
	if (c.scans == 0 || t_s - c.last_s > m_options.memory_s)
		c = TCell{t_s, t_s, 0};  // new, or forgotten
	else if (t_s - c.last_s > m_options.max_gap_s)
		c.run_start_s = t_s, c.scans = 0;  // a new run; established structure stays in memory
	c.last_s = t_s;
	++c.scans;
	if (c.established_s == std::numeric_limits<double>::infinity() && c.scans >= m_options.min_scans &&
		c.last_s - c.run_start_s >= m_options.min_span_s)
		c.established_s = t_s;
}

void CStaticEvidenceGrid::prune(double t_s)
{
	// Forget cells not hit within the memory (about every half memory).
	if (t_s - m_lastPrune_s < 0.5 * m_options.memory_s) return;
	m_lastPrune_s = t_s;
	for (auto it = m_cells.begin(); it != m_cells.end();)
		it = t_s - it->second.last_s > m_options.memory_s ? m_cells.erase(it) : std::next(it);
}

void CStaticEvidenceGrid::insert(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose,
								 double t_s, const std::vector<bool>* skip)
{
	prune(t_s);
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	for (size_t b = 0; b < scan.getScanSize(); ++b)
	{
		const double r = scan.getScanRange(b);
		if (!scan.getScanRangeValidity(b) || !std::isfinite(r) || r <= 0 || r > m_options.max_range_m) continue;
		if (skip && b < skip->size() && (*skip)[b]) continue;
		const double a = beamBearing(scan, b);
		double wx = 0, wy = 0;
		robotPose.composePoint(sx + r * std::cos(a), sy + r * std::sin(a), wx, wy);
		hit(keyOf(index(wx), index(wy)), t_s);
	}
}

double CStaticEvidenceGrid::staticSince(const mrpt::math::TPoint2D& p, double t_s) const
{
	double since = std::numeric_limits<double>::infinity();
	const int cx = index(p.x), cy = index(p.y);
	const int n = static_cast<int>(std::ceil(m_options.radius_m / m_options.resolution_m));
	const double res = m_options.resolution_m, r2 = m_options.radius_m * m_options.radius_m;
	for (int dx = -n; dx <= n; ++dx)
		for (int dy = -n; dy <= n; ++dy)
		{
			// Distance from p to the nearest point of the cell.
			const double x0 = (cx + dx) * res, y0 = (cy + dy) * res;
			const double ex = std::max({x0 - p.x, 0.0, p.x - (x0 + res)}), ey = std::max({y0 - p.y, 0.0, p.y - (y0 + res)});
			if (ex * ex + ey * ey > r2) continue;
			const auto it = m_cells.find(keyOf(cx + dx, cy + dy));
			if (it != m_cells.end() && t_s - it->second.last_s <= m_options.memory_s)
				since = std::min(since, it->second.established_s);
		}
	return since;
}

}  // namespace hslam::dynamic
