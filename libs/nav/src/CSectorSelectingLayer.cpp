/* hslam nav: sector selecting layer (thesis figure 61; gaps: see the header). */
#include <hslam/nav/CSectorSelectingLayer.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::nav
{
double CSectorSelectingLayer::gapHeading(double ex, double ey, double qx, double qy) const
{
	const double cx = 0.5 * (ex + qx), cy = 0.5 * (ey + qy), w = std::hypot(qx - ex, qy - ey);
	// Axis n: perpendicular to the gap, pointing away from the robot (at the origin).
	double nx = -(qy - ey) / w, ny = (qx - ex) / w;
	if (nx * cx + ny * cy < 0) nx = -nx, ny = -ny;
	const double t0 = -(cx * nx + cy * ny);  // robot's position along the axis (< 0: before the gap)
	const double e = std::abs(cx * ny - cy * nx);  // robot's distance from the axis
	const double hw = 1e-3 * (m_opts.robot_half_width_mm + m_opts.margin_mm);
	const double slack = std::max(0.0, 0.5 * w - hw);
	const double look = 1e-3 * m_opts.lookahead_mm;
	// Line up first: the aim point stays approach_gain * e before the gap until
	// the robot is within half the slack of the axis, then runs ahead along it.
	const double t = e <= 0.5 * slack ? t0 + look : std::min(t0 + look, -m_opts.approach_gain * e);
	const double ax = cx + t * nx, ay = cy + t * ny;
	if (std::hypot(ax, ay) < 0.05) return std::atan2(ny, nx);  // at the aim point: face through the gap
	return std::atan2(ay, ax);
}

void CSectorSelectingLayer::findGaps(const CPolarProfile& p, double tx, double ty, std::vector<TGap>& gaps) const
{
	gaps.clear();
	const int n = static_cast<int>(p.size());
	const double hw = 1e-3 * (m_opts.robot_half_width_mm + m_opts.margin_mm);
	const double need = 2.0 * hw, depth = 2.0 * hw, maxW = 1e-3 * m_opts.max_gap_width_mm;
	const double maxR = p.maxRange();
	const int half = static_cast<int>(m_opts.gap_field_rad / p.binSize());
	auto idx = [n](int k) { return ((k % n) + n) % n; };  // k: bins from ahead, CCW positive
	for (int k = -half; k < half; ++k)
	{
		const int a = idx(k), b = idx(k + 1);  // b is CCW of a
		const double ra = p.range(a), rb = p.range(b);
		int edge, dir;  // near edge bin, search direction (+1 CCW) into the opening
		if (rb - ra > depth) edge = a, dir = +1;
		else if (ra - rb > depth) edge = b, dir = -1;
		else continue;
		const double ex = p.pointX(edge), ey = p.pointY(edge);
		// The other side: the obstacle point nearest the edge beyond the discontinuity.
		double best2 = 1e18, qx = 0, qy = 0;
		for (int j = (dir > 0 ? k + 1 : k); j >= -half && j <= half; j += dir)
		{
			const int i = idx(j);
			if (p.range(i) >= maxR) continue;
			const double dx = p.pointX(i) - ex, dy = p.pointY(i) - ey, d2 = dx * dx + dy * dy;
			if (d2 < best2) best2 = d2, qx = p.pointX(i), qy = p.pointY(i);
		}
		const double best = std::sqrt(best2);
		if (best < need || best > maxW) continue;
		const double cx = 0.5 * (ex + qx), cy = 0.5 * (ey + qy);
		bool dup = false;
		for (const auto& g : gaps)
			if (std::hypot(0.5 * (g.ex + g.qx) - cx, 0.5 * (g.ey + g.qy) - cy) < 0.2) dup = true;
		if (dup) continue;
		TGap g{ex, ey, qx, qy, best, gapHeading(ex, ey, qx, qy), 0};
		g.cost_m = std::hypot(cx, cy) + std::hypot(tx - cx, ty - cy);
		gaps.push_back(g);
	}
}

void CSectorSelectingLayer::pickClearSides(const std::vector<double>& freeOf, int n, double targetBearing,
											TSectorChoice& out, double& freeLeft, double& freeRight) const
{
	double bestLeft = -1, bestRight = -1;
	for (int k = 0; k <= n; ++k)
	{
		for (const int kk : {k, -k})
		{
			const double h = kk * m_opts.step_rad, free = freeOf[kk + n];
			if (free < 1e-3 * m_opts.clear_distance_mm) continue;
			// Among clear directions each side prefer the longest free corridor,
			// then the one nearest the target bearing.
			const double score = free - 0.1 * std::abs(mrpt::math::wrapToPi(h - targetBearing));
			if (h >= 0 && score > bestLeft) bestLeft = score, out.left_rad = h, freeLeft = free;
			if (h <= 0 && score > bestRight) bestRight = score, out.right_rad = h, freeRight = free;
		}
	}
}

TSectorChoice CSectorSelectingLayer::evaluate(const CPolarProfile& profile, double targetBearing,
											  double targetDistance) const
{
	TSectorChoice out;
	const double halfWidth = 1e-3 * (m_opts.robot_half_width_mm + m_opts.margin_mm);
	const double need = std::min(1e-3 * m_opts.clear_distance_mm, targetDistance);
	out.target_clear = profile.corridorFreeDistance(targetBearing, halfWidth) >= need;
	const int n = static_cast<int>(std::floor(m_opts.search_half_angle_rad / m_opts.step_rad + 1e-9));
	profile.corridorFreeDistances(m_opts.step_rad, n, halfWidth, m_freeScratch);  // reused: no allocation per step
	double freeLeft = 0, freeRight = 0;
	pickClearSides(m_freeScratch, n, targetBearing, out, freeLeft, freeRight);
	out.any_clear = out.left_rad || out.right_rad;
	if (out.target_clear)
	{
		out.chosen_rad = targetBearing;
		return out;
	}
	if (!m_opts.use_gaps)
	{
		if (out.left_rad && out.right_rad)  // target seeking subsumes the farther candidate
			out.chosen_rad = std::abs(*out.left_rad - targetBearing) <= std::abs(*out.right_rad - targetBearing)
								 ? *out.left_rad
								 : *out.right_rad;
		else if (out.any_clear)
			out.chosen_rad = out.left_rad ? *out.left_rad : *out.right_rad;
		return out;
	}
	// Tangent-bug choice among the sectors (P: end of the free corridor, at most
	// as far as the target) and the passable gaps (P: the gap's middle).
	const double tx = targetDistance * std::cos(targetBearing), ty = targetDistance * std::sin(targetBearing);
	auto sectorCost = [&](double h, double free)
	{
		const double f = std::min(free, targetDistance);
		const double px = f * std::cos(h), py = f * std::sin(h);
		return f + std::hypot(tx - px, ty - py);
	};
	double best = 1e18;
	if (out.left_rad) best = sectorCost(*out.left_rad, freeLeft), out.chosen_rad = *out.left_rad;
	if (out.right_rad)
	{
		const double c = sectorCost(*out.right_rad, freeRight);
		if (c < best) best = c, out.chosen_rad = *out.right_rad;
	}
	findGaps(profile, tx, ty, out.gaps);
	for (size_t i = 0; i < out.gaps.size(); ++i)
		if (out.gaps[i].cost_m < best)
			best = out.gaps[i].cost_m, out.chosen_rad = out.gaps[i].heading_rad, out.chosen_gap = static_cast<int>(i);
	return out;
}
}  // namespace hslam::nav
