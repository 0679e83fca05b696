#include <hslam/matching/icp_covariance.h>

#include "point_scatter.h"
#include "reference_points.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace hslam::matching
{
using detail::TIndexReference;
using detail::TMrptReference;

namespace
{
/** Unit normal of the reference points idx (PCA: smallest eigenvector). */
template <class Reference>
bool fitNormal(const Reference& ref, const std::vector<size_t>& idx, Eigen::Vector2d& normal)
{
	if (idx.size() < 3) return false;
	const auto eig = detail::scatterOf(idx.size(), [&](size_t j) { return ref.point(idx[j]); });
	if (eig.eigenvalues()[1] <= 0 || eig.eigenvalues()[0] > 0.25 * eig.eigenvalues()[1]) return false;  // not a line
	normal = eig.eigenvectors().col(0);
	return true;
}
}  // namespace

namespace
{
/** Point-to-line normal equations of `count` current points (robot frame,
 * `pointAt(k)`) at `pose`: H = sum J J', g = sum J r, r the signed distance
 * along the reference normal, J = [n_x, n_y, n . d(R p)/dtheta]. */
struct TNormalEquations
{
	Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
	Eigen::Vector3d g = Eigen::Vector3d::Zero();
	double residual2 = 0;
	size_t matched = 0;
	double weight = 0;  //!< matched points, each counted by its spacing weight
};

/** How much of an independent measurement current point p = pointAt(k)
 * is: its distance to the previous point in scan order (the next, for the
 * first) over spacing_m, at most 1; 1 for every point when spacing_m is 0. */
template <class PointAt>
double spacingWeight(const mrpt::math::TPoint2D& p, size_t k, size_t count, PointAt pointAt, double spacing_m)
{
	if (spacing_m <= 0 || count < 2) return 1.0;
	const mrpt::math::TPoint2D q = pointAt(k > 0 ? k - 1 : 1);
	return std::min(1.0, std::hypot(p.x - q.x, p.y - q.y) / spacing_m);
}

template <class Reference, class PointAt>
TNormalEquations normalEquations(const Reference& reference, size_t count, PointAt pointAt,
								 const mrpt::poses::CPose2D& pose, const TGeometricCovarianceOptions& o)
{
	TNormalEquations e;
	std::vector<size_t> idx;
	std::vector<float> dist2;
	for (size_t k = 0; k < count; ++k)
	{
		const mrpt::math::TPoint2D p = pointAt(k);
		const auto w = pose + p;
		reference.nearest(static_cast<float>(w.x), static_cast<float>(w.y), static_cast<size_t>(o.normal_neighbours),
						  idx, dist2);
		if (idx.empty() || dist2[0] > o.max_match_distance_m * o.max_match_distance_m) continue;
		Eigen::Vector2d n;
		if (!fitNormal(reference, idx, n)) continue;
		const Eigen::Vector2d q = reference.point(idx[0]);
		const Eigen::Vector2d arm(w.x - pose.x(), w.y - pose.y());  // R p
		const Eigen::Vector3d J(n.x(), n.y(), n.x() * -arm.y() + n.y() * arm.x());
		const double r = n.dot(Eigen::Vector2d(w.x, w.y) - q);
		const double weight = spacingWeight(p, k, count, pointAt, o.full_weight_spacing_m);
		e.H += weight * J * J.transpose();
		e.g += weight * J * r;
		e.residual2 += weight * r * r;
		e.weight += weight;
		++e.matched;
	}
	return e;
}

/** The covariance for `count` current points given by `pointAt(k)` (robot frame). */
template <class Reference, class PointAt>
Eigen::Matrix3d alignmentCovariance(const Reference& reference, size_t count, PointAt pointAt,
									const mrpt::poses::CPose2D& pose, const TGeometricCovarianceOptions& o,
									size_t* matchedPoints)
{
	const TNormalEquations e = normalEquations(reference, count, pointAt, pose, o);
	const Eigen::Matrix3d& H = e.H;
	const double residual2 = e.residual2;
	const size_t matched = e.matched;
	if (matchedPoints) *matchedPoints = matched;
	const double cap2 = o.max_std_m * o.max_std_m;
	// (a weight of 0: every matched point on top of its predecessor)
	if (matched < 10 || !(e.weight > 0)) return Eigen::Matrix3d::Identity() * cap2;
	const double sigma2 = std::max(residual2 / e.weight, o.min_sigma_m * o.min_sigma_m) * o.correlation_factor;
	// Invert through the eigen-decomposition, capping the variance of
	// unconstrained directions instead of dividing by ~0.
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(H);
	Eigen::Vector3d inv;
	for (int i = 0; i < 3; ++i) inv[i] = std::min(sigma2 / std::max(eig.eigenvalues()[i], 1e-12), cap2);
	Eigen::Matrix3d cov = eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
	// A translation direction constrained by fewer than degenerate_min_fraction
	// of the matched points (unit-weight information of the translation
	// block: each point counts along its normal) is unconstrained. Rotation
	// is left as it is: heading is what matching must keep correcting.
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> tr(H.topLeftCorner<2, 2>());
	const double minEigen = o.degenerate_min_fraction * e.weight;
	for (int i = 0; i < 2; ++i)
		if (tr.eigenvalues()[i] < minEigen)
			cov.topLeftCorner<2, 2>() += cap2 * tr.eigenvectors().col(i) * tr.eigenvectors().col(i).transpose();
	return cov;
}

/** alignmentCovariance() for current points held in an MRPT point map. */
template <class Reference>
Eigen::Matrix3d mapAlignmentCovariance(const Reference& reference, const mrpt::maps::CSimplePointsMap& current,
									   const mrpt::poses::CPose2D& pose, const TGeometricCovarianceOptions& o,
									   size_t* matchedPoints)
{
	const auto& xs = current.getPointsBufferRef_x();
	const auto& ys = current.getPointsBufferRef_y();
	return alignmentCovariance(
		reference, current.size(), [&](size_t k) { return mrpt::math::TPoint2D(xs[k], ys[k]); }, pose, o,
		matchedPoints);
}
}  // namespace

Eigen::Matrix3d geometricAlignmentCovariance(const mrpt::maps::CSimplePointsMap& reference,
											 const mrpt::maps::CSimplePointsMap& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& o, size_t* matchedPoints)
{
	return mapAlignmentCovariance(TMrptReference{reference}, current, pose, o, matchedPoints);
}

Eigen::Matrix3d geometricAlignmentCovariance(const mrpt::maps::CSimplePointsMap& reference,
											 const std::vector<mrpt::math::TPoint2D>& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& o, size_t* matchedPoints)
{
	return alignmentCovariance(
		TMrptReference{reference}, current.size(), [&](size_t k) { return current[k]; }, pose, o, matchedPoints);
}

Eigen::Matrix3d geometricAlignmentCovariance(const CPointIndex2D& reference,
											 const mrpt::maps::CSimplePointsMap& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& o, size_t* matchedPoints)
{
	return mapAlignmentCovariance(TIndexReference{reference}, current, pose, o, matchedPoints);
}

mrpt::poses::CPose2D refinedAlongNormals(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
										 mrpt::poses::CPose2D pose, const TGeometricCovarianceOptions& o, int steps)
{
	const auto& xs = current.getPointsBufferRef_x();
	const auto& ys = current.getPointsBufferRef_y();
	const auto pointAt = [&](size_t k) { return mrpt::math::TPoint2D(xs[k], ys[k]); };
	for (int step = 0; step < steps; ++step)
	{
		const TNormalEquations e = normalEquations(TIndexReference{reference}, current.size(), pointAt, pose, o);
		if (e.matched < 10) break;
		// Damped (Levenberg): a direction no normal constrains (a corridor's
		// axis) has no gradient either and stays where point-to-point ICP
		// left it.
		const Eigen::Matrix3d A = e.H + Eigen::Matrix3d::Identity() * (1e-3 * e.H.trace() / 3.0 + 1e-9);
		const Eigen::Vector3d d = -A.ldlt().solve(e.g);
		pose = mrpt::poses::CPose2D(pose.x() + d[0], pose.y() + d[1], pose.phi() + d[2]);
		if (std::hypot(d[0], d[1]) < 1e-4 && std::abs(d[2]) < 1e-5) break;
	}
	return pose;
}

}  // namespace hslam::matching
