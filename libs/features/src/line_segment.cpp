/* hslam: methods of TLineSegment (see line_segment.h). */
#include <hslam/features/line_segment.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::features
{
double TLineSegment::length_m() const { return std::hypot(p1.x - p0.x, p1.y - p0.y); }

double TLineSegment::directionAngle_rad() const
{
	return mrpt::math::wrapToPi(std::atan2(p1.y - p0.y, p1.x - p0.x));
}

mrpt::math::TPoint2D TLineSegment::midpoint() const { return {0.5 * (p0.x + p1.x), 0.5 * (p0.y + p1.y)}; }

std::optional<std::pair<double, double>> TLineSegment::slopeIntercept() const
{
	// x cos(a) + y sin(a) = rho  =>  y = -cot(a) x + rho / sin(a)
	const double s = std::sin(alpha_rad);
	if (std::abs(s) < 1e-9) return std::nullopt;
	return std::make_pair(-std::cos(alpha_rad) / s, rho_m / s);
}

double TLineSegment::distanceTo(const mrpt::math::TPoint2D& p) const
{
	return p.x * std::cos(alpha_rad) + p.y * std::sin(alpha_rad) - rho_m;
}

}  // namespace hslam::features
