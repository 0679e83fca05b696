/* hslam vision: scoring on the exact plane-warp pairs (plane_warp.h), shared
 * by the tests and `hslam-bench vision` (not used by the algorithms). */
#pragma once

#include <hslam/vision/CFlowAnalyzer.h>
#include <hslam/vision/plane_warp.h>

#include <vector>

namespace hslam::vision
{
struct TFoeErrors
{
	std::vector<double> lsq_px;  //!< |least-squares FOE - true FOE| per pair with a valid FOE
	std::vector<double> lsq_x_px;  //!< |least-squares x - true x|, same pairs (compare with the vote's x)
	std::vector<double> vote_x_px;  //!< |vote x - true x| per pair with a vote
	size_t invalid = 0;  //!< pairs without a least-squares FOE
};

/** FOE errors over `pairs` scenario pairs (k = 0..pairs-1) analysed with `model`. */
TFoeErrors foeErrorsOnScenario(const TMountedCamera& camera, EPlaneMotion motion, int pairs, uint64_t seed,
							   const IRotationFlowModel* model, const TVisionOptions& options);

/** Tracked flow of the pure-rotation pairs k0..k1-1 as (corner, flow, robot
 * yaw) samples. With maxTrackError_px > 0, tracks farther than that from
 * the true motion (the pair's homography) are left out and counted in
 * `dropped`: they are tracker failures, not errors of a rotation model. */
std::vector<TRotationSample> rotationSamplesOnScenario(const TMountedCamera& camera, int k0, int k1, uint64_t seed,
													   const TFlowOptions& flowOptions, double maxTrackError_px = 0,
													   size_t* dropped = nullptr);

/** RMS (px) of measured minus predicted flow. */
double rotationResidualRms(const IRotationFlowModel& model, const std::vector<TRotationSample>& samples);

/** True FOE (px) in the second image of a robot motion `robotDelta` (robot 2
 * in robot 1) seen by `camera`: K t / t_z with t the camera translation in
 * the second camera frame (R^T t_M of cameraMotion). */
cv::Point2d trueFoeOfRobotMotion(const TMountedCamera& camera, const mrpt::poses::CPose3D& robotDelta);

/** Median (NaN for none). */
double medianOf(std::vector<double> values);

}  // namespace hslam::vision
