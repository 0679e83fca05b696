#include <hslam/matching/point_translation.h>

#include <hslam/matching/icp_covariance.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace hslam::matching
{
namespace
{
/** Neighbouring laser points are strongly correlated and translation-only
 * association can lock onto a wrong wall, so the covariance is not divided by
 * the number of points: the RMS residual itself (at least 5 cm) is the std in
 * every direction the geometry constrains. Along a direction it does not
 * constrain (a corridor's axis: every wall normal is across it) point-to-point
 * association is biased towards no motion, so the variance there comes from
 * the geometry (icp_covariance: huge), and the filter keeps odometry's value.
 * Without surfaces (fewer than 10 points on line-like neighbourhoods:
 * isolated points, which constrain both directions) it stays isotropic
 * (issue 12, "long featureless corridor": the isotropic 5 cm made the estimate
 * lose 8 % of the travel along a 200 m simulated corridor). */
Eigen::Matrix2d translationCovariance(const mrpt::maps::CSimplePointsMap& previousMap,
									  const std::vector<mrpt::math::TPoint2D>& current, double phi,
									  const TPointTranslationResult& r)
{
	const double floor2 = std::max(r.rms_m * r.rms_m, 0.05 * 0.05);
	const mrpt::poses::CPose2D pose(r.translation_m.x(), r.translation_m.y(), phi);
	size_t onSurfaces = 0;
	const Eigen::Matrix3d geo =
		geometricAlignmentCovariance(previousMap, current, pose, TGeometricCovarianceOptions(), &onSurfaces);
	if (onSurfaces < 10) return Eigen::Matrix2d::Identity() * floor2;  // no walls: isolated points constrain both ways
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(geo.topLeftCorner<2, 2>());
	const Eigen::Vector2d variance = eig.eigenvalues().cwiseMax(floor2);
	return eig.eigenvectors() * variance.asDiagonal() * eig.eigenvectors().transpose();
}
}  // namespace

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
	r.covariance = translationCovariance(previousMap, current, phi, r);
	return r;
}

}  // namespace hslam::matching
