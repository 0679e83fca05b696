/* hslam: human-readable table of a trajectory evaluation. */
#pragma once

#include <hslam/eval/evaluate_trajectory.h>

#include <ostream>

namespace hslam::eval
{
/** Prints inputs, matching counts, alignment, ATE and one RPE row per pair
 * family ("no pairs" rows when the reference path is too short). Leaves the
 * stream's formatting flags untouched. */
void printEvaluation(std::ostream& os, const TTrajectoryErrors& errors);

}  // namespace hslam::eval
