/* hslam: the thesis' point-based translation estimate ("method 1" of 4.4.2
 * iii): with the rotation already known, rotate the points of one frame and
 * find the translation that brings them onto the other frame's points, with
 * a Gaussian weight that rules out bad pairs. Done here as a few iterations of
 * nearest-neighbour association (k-d tree) with a shrinking gate; used when
 * too few lines pair for the line-based least squares. */
#pragma once

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>

#include <Eigen/Core>

#include <vector>

namespace hslam::matching
{
struct TPointTranslationResult
{
	Eigen::Vector2d translation_m = Eigen::Vector2d::Zero();  //!< t with previous = R(phi) current + t
	Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();
	size_t inliers = 0;
	double rms_m = 0;  //!< RMS residual of the inliers
};

/** Translation t such that R(phi) * current + t lands on `previousMap`,
 * starting from `initialTranslation`. Gate shrinks from startGate_m to endGate_m. */
TPointTranslationResult estimatePointTranslation(const mrpt::maps::CSimplePointsMap& previousMap,
												 const std::vector<mrpt::math::TPoint2D>& current, double phi_rad,
												 const Eigen::Vector2d& initialTranslation, double startGate_m,
												 double endGate_m, int iterations);

}  // namespace hslam::matching
