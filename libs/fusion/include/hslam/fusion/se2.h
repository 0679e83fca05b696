/* hslam: small SE(2) helpers on plain Eigen vectors (x, y, theta), used by the
 * UKF so its sigma points need no MRPT objects. Angles in rad. */
#pragma once

#include <Eigen/Core>

namespace hslam::fusion
{
using TPoseVec = Eigen::Vector3d;  //!< (x m, y m, theta rad)

/** Wraps an angle to (-pi, pi]. */
double wrapToPi(double angle_rad);

/** a (+) b: pose b expressed in frame a, composed (MRPT's CPose2D operator+). */
TPoseVec compose(const TPoseVec& a, const TPoseVec& b);

/** a (-) b: pose a expressed in the frame of b (MRPT's CPose2D operator-). */
TPoseVec inverseCompose(const TPoseVec& a, const TPoseVec& b);

/** Weighted mean of poses; theta is averaged on the circle (atan2 of the
 * weighted sines and cosines), so poses on either side of +-pi average
 * correctly (thesis figure 113 problem). Weights may be negative (UKF). */
TPoseVec weightedPoseMean(const Eigen::Matrix3Xd& poses, const Eigen::VectorXd& weights);

}  // namespace hslam::fusion
