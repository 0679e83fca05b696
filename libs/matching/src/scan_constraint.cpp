#include <hslam/matching/scan_constraint.h>

#include "point_scatter.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace hslam::matching
{
namespace
{
constexpr double kMaxLineAcrossRms_m = 0.03;
constexpr double kSparseReachRadii = 3.0;

double distance(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

/** The information one point adds (unit weight): n n' for a line-like
 * neighbourhood, I / 2 otherwise; zero without enough neighbours. */
Eigen::Matrix2d pointInformation(const std::vector<mrpt::math::TPoint2D>& pts, size_t k, double radius_m)
{
	size_t first = k, last = k;
	while (first > 0 && distance(pts[first - 1], pts[k]) <= radius_m) --first;
	while (last + 1 < pts.size() && distance(pts[last + 1], pts[k]) <= radius_m) ++last;
	// a wall sampled sparsely (an end wall 6 m ahead, 1 deg beams: every
	// 10 cm) still gets two neighbours on each side, up to 3 radii away
	const double reach_m = kSparseReachRadii * radius_m;
	while (k - first < 2 && first > 0 && distance(pts[first - 1], pts[k]) <= reach_m) --first;
	while (last - k < 2 && last + 1 < pts.size() && distance(pts[last + 1], pts[k]) <= reach_m) ++last;
	if (last - first + 1 < 4) return Eigen::Matrix2d::Zero();
	const auto eig = detail::scatterOf(last - first + 1, [&](size_t j)
									   { return Eigen::Vector2d(pts[first + j].x, pts[first + j].y); });
	// A corner or a pillar spreads across by more than range noise does
	// (a few centimetres); a sparse stretch of wall, four points 10 cm apart
	// with 1 cm of noise, is still a line (as a ratio of spreads it was not,
	// and a bare corridor's far walls "constrained" its axis).
	const double acrossRms_m = std::sqrt(std::max(0.0, eig.eigenvalues()[0]) / static_cast<double>(last - first + 1));
	if (acrossRms_m > kMaxLineAcrossRms_m && eig.eigenvalues()[0] > 0.01 * eig.eigenvalues()[1])
		return 0.5 * Eigen::Matrix2d::Identity();
	const Eigen::Vector2d n = eig.eigenvectors().col(0);
	return n * n.transpose();
}
}  // namespace

TScanConstraint scanTranslationConstraint(const std::vector<mrpt::math::TPoint2D>& points, double radius_m,
										  double full_weight_spacing_m)
{
	TScanConstraint out;
	Eigen::Matrix2d info = Eigen::Matrix2d::Zero();
	double total = 0;
	for (size_t k = 0; k < points.size(); ++k)
	{
		const Eigen::Matrix2d I = pointInformation(points, k, radius_m);
		if (I.trace() <= 0) continue;
		const double spacing = points.size() > 1 ? distance(points[k], points[k > 0 ? k - 1 : 1]) : 0.0;
		const double w = full_weight_spacing_m > 0 ? std::min(1.0, spacing / full_weight_spacing_m) : 1.0;
		info += w * I, total += w, ++out.points;
	}
	if (!(total > 0)) return out;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(info);
	out.weakest = eig.eigenvectors().col(0);
	out.weakest_fraction = std::max(0.0, eig.eigenvalues()[0]) / total;
	return out;
}

}  // namespace hslam::matching
