/* hslam: matching the poses of an estimated trajectory to those of a
 * reference trajectory by timestamp, the first step of any evaluation. */
#pragma once

#include <hslam/common/tum_trajectory.h>

#include <cstddef>

namespace hslam::eval
{
/** First and last timestamp of a trajectory, whatever the order of its poses. */
struct TTimeRange
{
	bool empty = true;  //!< true for a trajectory without poses
	double first_s = 0;
	double last_s = 0;
};

TTimeRange timeRange(const common::TTrajectory2D& trajectory);

/** Pairs of poses that belong together, sorted by estimate timestamp. */
struct TAssociation
{
	common::TTrajectory2D reference;  //!< matched reference poses
	common::TTrajectory2D estimate;  //!< matched estimate poses (same size and order)
	size_t unmatched_reference = 0;  //!< reference poses no estimate pose took
	size_t unmatched_estimate = 0;  //!< estimate poses without a reference pose within max_dt

	size_t size() const { return reference.size(); }
};

/** Gives each estimate pose the nearest reference pose with |dt| <= max_dt_s,
 * using every reference pose at most once. Candidate pairs are taken in order
 * of increasing |dt| (as TUM's associate.py does), so when two estimate poses
 * compete for one reference pose the closer one in time wins. The inputs may
 * be in any order. Cost grows with the number of reference poses inside each
 * +-max_dt_s window. Throws std::invalid_argument if max_dt_s is negative or
 * not finite. */
TAssociation associateByTimestamp(const common::TTrajectory2D& reference,
								  const common::TTrajectory2D& estimate, double max_dt_s);

}  // namespace hslam::eval
