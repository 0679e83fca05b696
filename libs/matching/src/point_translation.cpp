#include <hslam/matching/point_translation.h>

#include <Eigen/LU>

#include <cmath>

namespace hslam::matching
{
TPointTranslationResult estimatePointTranslation(const mrpt::maps::CSimplePointsMap& previousMap,
												 const std::vector<mrpt::math::TPoint2D>& current, double phi,
												 const Eigen::Vector2d& initial, double startGate, double endGate,
												 int iterations)
{
	TPointTranslationResult r;
	r.translation_m = initial;
	if (previousMap.size() == 0 || current.empty()) return r;
	const double c = std::cos(phi), s = std::sin(phi);
	for (int it = 0; it < iterations; ++it)
	{
		const double gate = iterations > 1 ? startGate + (endGate - startGate) * it / (iterations - 1.0) : endGate;
		const double sigma2 = 0.25 * gate * gate;  // Gaussian weight, gate = 2 sigma
		Eigen::Vector2d sum = Eigen::Vector2d::Zero();
		double weightSum = 0, sq = 0;
		size_t inliers = 0;
		for (const auto& p : current)
		{
			const double x = c * p.x - s * p.y + r.translation_m.x();
			const double y = s * p.x + c * p.y + r.translation_m.y();
			float nx, ny, d2;
			previousMap.kdTreeClosestPoint2D(static_cast<float>(x), static_cast<float>(y), nx, ny, d2);
			if (d2 > gate * gate) continue;
			const double w = std::exp(-0.5 * d2 / sigma2);
			sum += w * Eigen::Vector2d(nx - x, ny - y);
			weightSum += w;
			sq += d2;
			++inliers;
		}
		if (weightSum <= 0) break;
		r.translation_m += sum / weightSum;
		r.inliers = inliers;
		r.rms_m = std::sqrt(sq / inliers);
	}
	const double var = r.rms_m * r.rms_m;
	// Neighbouring laser points are strongly correlated and translation-only
	// association can lock onto a wrong wall, so the covariance is not divided
	// by the number of points: the RMS residual itself (at least 5 cm) is the std.
	r.covariance = Eigen::Matrix2d::Identity() * std::max(var, 0.05 * 0.05);
	return r;
}

}  // namespace hslam::matching
