#include <hslam/sonar/tbf_geometry.h>

#include <algorithm>
#include <cmath>

namespace hslam::sonar
{
using mrpt::math::TPoint2D;

std::optional<std::array<TPoint2D, 2>> circleCircleIntersection(const TPoint2D& c1, double r1, const TPoint2D& c2,
																double r2)
{
	const double dx = c1.x - c2.x, dy = c1.y - c2.y;  // eq. 45-46
	const double ds2 = dx * dx + dy * dy;  // eq. 47
	if (!(ds2 > 1e-18) || r1 < 0 || r2 < 0) return std::nullopt;
	const double ds = std::sqrt(ds2);
	const double k = (ds2 + r1 * r1 - r2 * r2) / (2.0 * ds);  // eq. 49
	const double h2 = r1 * r1 - k * k;
	if (h2 < 0)
	{
		// Tangent circles can miss by rounding: accept a relative slack.
		if (h2 < -1e-12 * (r1 * r1 + 1.0)) return std::nullopt;
	}
	const double h = std::sqrt(std::max(0.0, h2));
	// eq. 43-44: T = s1 - (1/ds) (d k -+ (-d_perp) h)
	const double mx = c1.x - dx * k / ds, my = c1.y - dy * k / ds;
	const double px = -dy / ds, py = dx / ds;
	return std::array<TPoint2D, 2>{TPoint2D(mx + px * h, my + py * h), TPoint2D(mx - px * h, my - py * h)};
}

std::optional<std::array<TPoint2D, 2>> wijkEq37Candidates(const TPoint2D& s1, double r1, const TPoint2D& s2, double r2)
{
	const double dxs = s1.x - s2.x, dys = s1.y - s2.y;  // eq. 39-40
	const double ds2 = dxs * dxs + dys * dys;  // eq. 41
	const double dr2 = (r1 * r1 - r2 * r2 - ds2) / 2.0;  // eq. 42
	const double rad = r2 * r2 * ds2 - dr2 * dr2;
	if (!(ds2 > 0) || rad < 0) return std::nullopt;
	const double root = std::sqrt(rad);
	// eq. 37-38, the two sign choices
	return std::array<TPoint2D, 2>{
		TPoint2D(s1.x + (dxs * dr2 + std::abs(dys) * root) / ds2, s1.y + (dys * dr2 + std::abs(dxs) * root) / ds2),
		TPoint2D(s1.x + (dxs * dr2 - std::abs(dys) * root) / ds2, s1.y + (dys * dr2 - std::abs(dxs) * root) / ds2)};
}

}  // namespace hslam::sonar
