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

double TLineFit::distanceTo(const mrpt::math::TPoint2D& p) const { return p.x * normal_x + p.y * normal_y - rho_m; }

mrpt::math::TPoint2D TLineFit::project(const mrpt::math::TPoint2D& p) const
{
	const double d = distanceTo(p);
	return {p.x - d * normal_x, p.y - d * normal_y};
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
	return fitLineTotalLeastSquares(points.data(), points.size());
}

TLineFit fitLineTotalLeastSquares(const mrpt::math::TPoint2D* first, size_t n)
{
	TLineFit fit;
	if (n < 2) return fit;
	const mrpt::math::TPoint2D* const last = first + n;
	double mx = 0, my = 0;
	for (const auto* q = first; q != last; ++q)
	{
		const auto& p = *q;
		mx += p.x;
		my += p.y;
	}
	mx /= static_cast<double>(n);
	my /= static_cast<double>(n);
	double sxx = 0, syy = 0, sxy = 0;  // scatter matrix about the centroid (eq. 63-64: K2 = sxy, K1 = sxx - syy)
	for (const auto* q = first; q != last; ++q)
	{
		const auto& p = *q;
		const double dx = p.x - mx, dy = p.y - my;
		sxx += dx * dx;
		syy += dy * dy;
		sxy += dx * dy;
	}
	if (sxx + syy <= 0) return fit;  // all points identical: no direction
	const double direction = 0.5 * std::atan2(2 * sxy, sxx - syy);  // eigenvector of the largest eigenvalue
	fit.centroid = {mx, my};
	normalFormThrough(fit.centroid, direction + M_PI / 2, fit.rho_m, fit.alpha_rad);
	fit.normal_x = std::cos(fit.alpha_rad);
	fit.normal_y = std::sin(fit.alpha_rad);
	double sum2 = 0, worst = 0;
	for (const auto* q = first; q != last; ++q)
	{
		const auto& p = *q;
		const double d = fit.distanceTo(p);
		sum2 += d * d;
		worst = std::max(worst, std::abs(d));
	}
	fit.rms_m = std::sqrt(sum2 / static_cast<double>(n));
	fit.max_residual_m = worst;
	const double ux = -fit.normal_y, uy = fit.normal_x;  // along the line
	double S = 0;
	for (const auto* q = first; q != last; ++q)
	{
		const auto& p = *q;
		const double s = (p.x - mx) * ux + (p.y - my) * uy;
		S += s * s;
	}
	const double sigma2 = n > 2 ? sum2 / static_cast<double>(n - 2) : 0.0;
	const double t = mx * ux + my * uy;
	fit.var_alpha_rad2 = S > 0 ? sigma2 / S : 0.0;
	fit.var_rho_m2 = sigma2 / static_cast<double>(n) + t * t * fit.var_alpha_rad2;
	fit.cov_rho_alpha_m_rad = t * fit.var_alpha_rad2;
	fit.valid = true;
	return fit;
}

}  // namespace hslam::features
