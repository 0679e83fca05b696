/* hslam: absolute trajectory error (ATE): position error of an estimate
 * after the best rigid SE(2) alignment onto the reference. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/error_stats.h>

#include <mrpt/math/TPose2D.h>

namespace hslam::eval
{
struct TAbsoluteTrajectoryError
{
	/** Transform applied to the estimate: alignment (+) estimate ~ reference. */
	mrpt::math::TPose2D alignment;
	/** Position errors |alignment (+) estimate_k - reference_k| (m). */
	TErrorStats position_m;
};

/** ATE of matched poses (reference[k] belongs to estimate[k]); headings are
 * not used. Throws std::invalid_argument if sizes differ or are zero. */
TAbsoluteTrajectoryError computeAbsoluteTrajectoryError(const common::TTrajectory2D& reference,
														const common::TTrajectory2D& estimate);

}  // namespace hslam::eval
