#include <hslam/matching/alignment_fit.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference_points.h"

namespace hslam::matching
{
namespace
{
/** Squared distance of q to the nearest reference segment (header comment):
 * from the nearest reference point to one of the next two nearest at most
 * maxSegment_m away from it; the nearest point's when there is none. */
template <class Reference>
double segmentDistance2(const Reference& reference, const Eigen::Vector2d& q, double maxSegment_m,
						std::vector<size_t>& idx, std::vector<float>& d2)
{
	reference.nearest(static_cast<float>(q.x()), static_cast<float>(q.y()), 3, idx, d2);
	if (idx.empty()) return 1e30;
	double best = d2[0];
	const Eigen::Vector2d a = reference.point(idx[0]);
	for (size_t j = 1; j < idx.size(); ++j)
	{
		const Eigen::Vector2d ab = reference.point(idx[j]) - a;
		const double length2 = ab.squaredNorm();
		if (length2 <= 0 || length2 > maxSegment_m * maxSegment_m) continue;
		const double t = std::clamp((q - a).dot(ab) / length2, 0.0, 1.0);
		best = std::min(best, (a + t * ab - q).squaredNorm());
	}
	return best;
}

template <class Reference>
double fitOf(const Reference& reference, const mrpt::maps::CSimplePointsMap& current, const mrpt::poses::CPose2D& pose,
			 double sigma_m, double maxSegment_m)
{
	const auto& xs = current.getPointsBufferRef_x();
	const auto& ys = current.getPointsBufferRef_y();
	if (xs.empty() || sigma_m <= 0) return 0;
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const double inv2s2 = 0.5 / (sigma_m * sigma_m);
	double sum = 0;
	std::vector<size_t> idx;
	std::vector<float> d2;
	for (size_t i = 0; i < xs.size(); ++i)
	{
		const double x = pose.x() + c * xs[i] - s * ys[i], y = pose.y() + s * xs[i] + c * ys[i];
		const double distance2 = maxSegment_m > 0
									 ? segmentDistance2(reference, Eigen::Vector2d(x, y), maxSegment_m, idx, d2)
									 : reference.nearestDistance2(static_cast<float>(x), static_cast<float>(y));
		sum += std::exp(-inv2s2 * distance2);
	}
	return sum / static_cast<double>(xs.size());
}
}  // namespace

double alignmentFit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m, double maxSegment_m)
{
	if (reference.empty()) return 0;
	return fitOf(detail::TMrptReference{reference}, current, pose, sigma_m, maxSegment_m);
}

double alignmentFit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m, double maxSegment_m)
{
	if (reference.empty()) return 0;
	return fitOf(detail::TIndexReference{reference}, current, pose, sigma_m, maxSegment_m);
}

}  // namespace hslam::matching
