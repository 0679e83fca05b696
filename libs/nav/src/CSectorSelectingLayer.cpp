/* hslam nav: sector selecting layer (thesis figure 61). */
#include <hslam/nav/CSectorSelectingLayer.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::nav
{
TSectorChoice CSectorSelectingLayer::evaluate(const CPolarProfile& profile, double targetBearing,
											  double targetDistance) const
{
	TSectorChoice out;
	const double halfWidth = 1e-3 * (m_opts.robot_half_width_mm + m_opts.margin_mm);
	const double need = std::min(1e-3 * m_opts.clear_distance_mm, targetDistance);
	out.target_clear = profile.corridorFreeDistance(targetBearing, halfWidth) >= need;
	double bestLeft = -1, bestRight = -1;
	for (double a = 0; a <= m_opts.search_half_angle_rad + 1e-9; a += m_opts.step_rad)
	{
		for (const double h : {a, -a})
		{
			const double free = profile.corridorFreeDistance(h, halfWidth);
			if (free < 1e-3 * m_opts.clear_distance_mm) continue;
			// Among clear directions each side prefer the longest free corridor,
			// then the one nearest the target bearing.
			const double score = free - 0.1 * std::abs(mrpt::math::wrapToPi(h - targetBearing));
			if (h >= 0 && score > bestLeft) bestLeft = score, out.left_rad = h;
			if (h <= 0 && score > bestRight) bestRight = score, out.right_rad = h;
		}
	}
	out.any_clear = out.left_rad || out.right_rad;
	if (out.target_clear)
		out.chosen_rad = targetBearing;
	else if (out.left_rad && out.right_rad)  // target seeking subsumes the farther candidate
		out.chosen_rad = std::abs(*out.left_rad - targetBearing) <= std::abs(*out.right_rad - targetBearing)
							 ? *out.left_rad
							 : *out.right_rad;
	else if (out.any_clear)
		out.chosen_rad = out.left_rad ? *out.left_rad : *out.right_rad;
	return out;
}
}  // namespace hslam::nav
