/* hslam: human-readable table of a trajectory evaluation. */
#pragma once

#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/eval/scan_consistency.h>

#include <ostream>

namespace hslam::eval
{
/** Prints inputs, matching counts, alignment, ATE and one RPE row per pair
 * family ("no pairs" rows when the reference path is too short). Leaves the
 * stream's formatting flags untouched. */
void printEvaluation(std::ostream& os, const TTrajectoryErrors& errors);

/** Prints the mean scan-pair misfit under each trajectory, how many pairs
 * each explains clearly worse, and the times of up to `listed` such pairs
 * per side (largest difference first). */
void printScanConsistency(std::ostream& os, const TScanConsistency& consistency, size_t listed = 10);

}  // namespace hslam::eval
