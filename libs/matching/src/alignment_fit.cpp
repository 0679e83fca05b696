#include <hslam/matching/alignment_fit.h>

#include <cmath>

#include "reference_points.h"

namespace hslam::matching
{
namespace
{
template <class Reference>
double fitOf(const Reference& reference, const mrpt::maps::CSimplePointsMap& current, const mrpt::poses::CPose2D& pose,
			 double sigma_m)
{
	const auto& xs = current.getPointsBufferRef_x();
	const auto& ys = current.getPointsBufferRef_y();
	if (xs.empty() || sigma_m <= 0) return 0;
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const double inv2s2 = 0.5 / (sigma_m * sigma_m);
	double sum = 0;
	for (size_t i = 0; i < xs.size(); ++i)
	{
		const double x = pose.x() + c * xs[i] - s * ys[i], y = pose.y() + s * xs[i] + c * ys[i];
		sum += std::exp(-inv2s2 * reference.nearestDistance2(static_cast<float>(x), static_cast<float>(y)));
	}
	return sum / static_cast<double>(xs.size());
}
}  // namespace

double alignmentFit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m)
{
	if (reference.empty()) return 0;
	return fitOf(detail::TMrptReference{reference}, current, pose, sigma_m);
}

double alignmentFit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m)
{
	if (reference.empty()) return 0;
	return fitOf(detail::TIndexReference{reference}, current, pose, sigma_m);
}

}  // namespace hslam::matching
