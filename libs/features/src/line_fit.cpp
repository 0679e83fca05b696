/* hslam: total-least-squares line fit in normal form (see line_fit.h). */
#include <hslam/features/line_fit.h>

#include <algorithm>
#include <cmath>

namespace hslam::features
{
namespace
{
/** Wraps to (-pi, pi]. */
double wrapHalfOpen(double a)
{
	a = std::remainder(a, 2 * M_PI);  // [-pi, pi]
	return a <= -M_PI ? a + 2 * M_PI : a;
}
}  // namespace

double TLineFit::distanceTo(const mrpt::math::TPoint2D& p) const
{
	return p.x * std::cos(alpha_rad) + p.y * std::sin(alpha_rad) - rho_m;
}

mrpt::math::TPoint2D TLineFit::project(const mrpt::math::TPoint2D& p) const
{
	const double d = distanceTo(p);
	return {p.x - d * std::cos(alpha_rad), p.y - d * std::sin(alpha_rad)};
}

void normalFormThrough(const mrpt::math::TPoint2D& point, double normal_rad, double& rho_m, double& alpha_rad)
{
	double rho = point.x * std::cos(normal_rad) + point.y * std::sin(normal_rad);
	if (rho < 0)
	{
		rho = -rho;
		normal_rad += M_PI;
	}
	rho_m = rho;
	alpha_rad = wrapHalfOpen(normal_rad);
}

double lineAngleDifference_rad(double alpha1_rad, double alpha2_rad)
{
	double d = std::abs(std::remainder(alpha1_rad - alpha2_rad, M_PI));  // [0, pi/2]
	return std::min(d, M_PI - d);
}

TLineFit fitLineTotalLeastSquares(const std::vector<mrpt::math::TPoint2D>& points)
{
	TLineFit fit;
	const size_t n = points.size();
	if (n < 2) return fit;
	double mx = 0, my = 0;
	for (const auto& p : points)
	{
		mx += p.x;
		my += p.y;
	}
	mx /= static_cast<double>(n);
	my /= static_cast<double>(n);
	double sxx = 0, syy = 0, sxy = 0;  // scatter matrix about the centroid (eq. 63-64: K2 = sxy, K1 = sxx - syy)
	for (const auto& p : points)
	{
		const double dx = p.x - mx, dy = p.y - my;
		sxx += dx * dx;
		syy += dy * dy;
		sxy += dx * dy;
	}
	if (sxx + syy <= 0) return fit;  // all points identical: no direction
	const double direction = 0.5 * std::atan2(2 * sxy, sxx - syy);  // eigenvector of the largest eigenvalue
	fit.centroid = {mx, my};
	normalFormThrough(fit.centroid, direction + M_PI / 2, fit.rho_m, fit.alpha_rad);
	double sum2 = 0, worst = 0;
	for (const auto& p : points)
	{
		const double d = fit.distanceTo(p);
		sum2 += d * d;
		worst = std::max(worst, std::abs(d));
	}
	fit.rms_m = std::sqrt(sum2 / static_cast<double>(n));
	fit.max_residual_m = worst;
	fit.valid = true;
	return fit;
}

}  // namespace hslam::features
