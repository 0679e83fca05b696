/* hslam nav: target seeking layer (thesis eq. 33). */
#include <hslam/nav/CTargetSeekingLayer.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::nav
{
TTargetSeekingOutput CTargetSeekingLayer::evaluate(const mrpt::math::TPose2D& pose,
												   const mrpt::math::TPoint2D& target) const
{
	TTargetSeekingOutput out;
	const double dx = target.x - pose.x, dy = target.y - pose.y;
	out.distance_m = std::hypot(dx, dy);
	out.bearing_rad = mrpt::math::wrapToPi(std::atan2(dy, dx) - pose.phi);
	out.reached = out.distance_m * 1e3 < m_opts.goal_tolerance_mm;
	const double d_mm = out.distance_m * 1e3;
	out.v_mps = 1e-3 * m_opts.max_speed_mm_s * d_mm / (d_mm + m_opts.half_speed_distance_mm);  // eq. 33
	return out;
}
}  // namespace hslam::nav
