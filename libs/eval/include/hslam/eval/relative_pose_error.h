/* hslam: relative pose error (RPE): error of the estimated relative motion
 * between two poses, for consecutive poses or poses a travelled distance
 * apart. Drift-sensitive and independent of any global alignment. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/error_stats.h>

#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace hslam::eval
{
/** Indices (i, j), i < j, into a pair of matched trajectories. */
using TIndexPair = std::pair<size_t, size_t>;

/** Path lengths tolerate this much rounding, so that ten steps of 0.1 m
 * count as 1 m. */
constexpr double PATH_LENGTH_TOLERANCE_M = 1e-9;

/** Cumulative path length (m) along the trajectory: element k is the length
 * of the polyline from pose 0 to pose k (element 0 is 0). */
std::vector<double> cumulativePathLength_m(const common::TTrajectory2D& trajectory);

/** (i, i+1) for every i. */
std::vector<TIndexPair> consecutivePairs(size_t numPoses);

/** For each i, the first j > i at which the path length along `reference`
 * from pose i reaches distance_m; i is skipped if it never does.
 * Throws std::invalid_argument unless distance_m > 0. */
std::vector<TIndexPair> pairsByTravelledDistance(const common::TTrajectory2D& reference, double distance_m);

/** error = (ref_i^-1 (+) ref_j)^-1 (+) (est_i^-1 (+) est_j): the estimated
 * relative motion seen from the true one (identity if they agree). */
mrpt::poses::CPose2D relativePoseError(const mrpt::poses::CPose2D& ref_i, const mrpt::poses::CPose2D& ref_j,
									   const mrpt::poses::CPose2D& est_i, const mrpt::poses::CPose2D& est_j);

/** RPE statistics over a set of pose pairs. */
struct TRelativePoseError
{
	TErrorStats trans_m;  //!< |translation of the error|, m
	TErrorStats rot_deg;  //!< |rotation of the error| wrapped to [0, 180], deg

	size_t pairs() const { return trans_m.count; }
};

/** RPE of matched trajectories (reference[k] belongs to estimate[k]) over
 * `pairs`. Throws std::invalid_argument if the sizes differ or a pair index
 * is out of range. */
TRelativePoseError computeRelativePoseError(const common::TTrajectory2D& reference,
											const common::TTrajectory2D& estimate,
											const std::vector<TIndexPair>& pairs);

}  // namespace hslam::eval
