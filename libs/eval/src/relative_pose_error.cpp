/* hslam: RPE pair selection and statistics. */
#include <hslam/eval/relative_pose_error.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hslam::eval
{
using mrpt::poses::CPose2D;

std::vector<double> cumulativePathLength_m(const common::TTrajectory2D& trajectory)
{
	std::vector<double> length_m(trajectory.size(), 0.0);
	for (size_t k = 1; k < trajectory.size(); ++k)
	{
		const auto& a = trajectory[k - 1].pose;
		const auto& b = trajectory[k].pose;
		length_m[k] = length_m[k - 1] + std::hypot(b.x - a.x, b.y - a.y);
	}
	return length_m;
}

std::vector<TIndexPair> consecutivePairs(size_t numPoses)
{
	std::vector<TIndexPair> pairs;
	for (size_t i = 0; i + 1 < numPoses; ++i) pairs.emplace_back(i, i + 1);
	return pairs;
}

std::vector<TIndexPair> pairsByTravelledDistance(const common::TTrajectory2D& reference, double distance_m)
{
	if (!(distance_m > 0) || !std::isfinite(distance_m))
		throw std::invalid_argument("RPE distance must be > 0 m, got " + std::to_string(distance_m));
	const std::vector<double> length_m = cumulativePathLength_m(reference);
	std::vector<TIndexPair> pairs;
	for (size_t i = 0; i < length_m.size(); ++i)
	{
		const double target_m = length_m[i] + distance_m - PATH_LENGTH_TOLERANCE_M;
		// lengths never decrease, so the first j reaching the target is a bound
		const auto it = std::lower_bound(length_m.begin() + static_cast<long>(i) + 1, length_m.end(), target_m);
		if (it == length_m.end()) break;  // later i reach even less far
		pairs.emplace_back(i, static_cast<size_t>(it - length_m.begin()));
	}
	return pairs;
}

CPose2D relativePoseError(const CPose2D& ref_i, const CPose2D& ref_j, const CPose2D& est_i, const CPose2D& est_j)
{
	// MRPT: a - b == b^-1 (+) a
	const CPose2D refMotion = ref_j - ref_i, estMotion = est_j - est_i;
	return estMotion - refMotion;
}

TRelativePoseError computeRelativePoseError(const common::TTrajectory2D& reference,
											const common::TTrajectory2D& estimate,
											const std::vector<TIndexPair>& pairs)
{
	if (reference.size() != estimate.size())
		throw std::invalid_argument("computeRelativePoseError: trajectories of different sizes");
	std::vector<double> trans_m, rot_deg;
	for (const auto& [i, j] : pairs)
	{
		if (i >= reference.size() || j >= reference.size())
			throw std::invalid_argument("computeRelativePoseError: pair index out of range");
		const CPose2D error = relativePoseError(CPose2D(reference[i].pose), CPose2D(reference[j].pose),
												CPose2D(estimate[i].pose), CPose2D(estimate[j].pose));
		trans_m.push_back(error.norm());
		rot_deg.push_back(mrpt::RAD2DEG(std::abs(mrpt::math::wrapToPi(error.phi()))));
	}
	return {computeErrorStats(trans_m), computeErrorStats(rot_deg)};
}

}  // namespace hslam::eval
