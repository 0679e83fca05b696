/* hslam vision: image pairs with exact ground truth, for tests and
 * benchmarks (not used by the algorithms).
 *
 * A plane n^T X = d (camera-1 frame) carries a procedural texture (random
 * grey rectangles, lightly blurred so it is band-limited). The first image is
 * the texture; the second is the first warped by the plane homography
 *     X2 = R X1 + t = (R + t n^T / d) X1   =>   H = K (R + t n^T / d) K^-1
 * (the brief's K (R - t n^T / d) K^-1 is the same with the plane written
 * n^T X + d = 0). The FOE of the second image is K t / t_z, and the flow of
 * the rotation alone is K R K^-1. The canvas is larger than the image, so the
 * second image has texture where the first had none. */
#pragma once

#include <hslam/vision/camera_geometry.h>
#include <opencv2/core.hpp>

#include <cstdint>

namespace hslam::vision
{
struct TPlanePairSpec
{
	cv::Matx33d K = cv::Matx33d::eye();
	cv::Size size{640, 480};
	cv::Matx33d R = cv::Matx33d::eye();  //!< X2 = R X1 + t
	cv::Vec3d t{0, 0, -0.05};  //!< m (camera moving forward: t_z < 0)
	cv::Vec3d n{0, 0, 1};  //!< unit plane normal, camera-1 frame
	double d_m = 3.0;  //!< plane distance
	double noise_grey = 1.0;  //!< sigma of additive Gaussian noise per image (grey levels)
	uint64_t seed = 1;
	double robot_yaw_rad = 0;  //!< the robot's yaw change (planePairForRobotMotion), for the rotation models
};

struct TPlanePair
{
	cv::Mat first, second;  //!< CV_8UC1
	cv::Matx33d H;
	cv::Point2d foe;  //!< K t / t_z in the second image
};

TPlanePair makePlanePair(const TPlanePairSpec& spec);

/** Spec for a robot motion `robotDelta` (robot 2 in robot 1) seen by `camera`:
 * camera 2 in camera 1 is M = (-S) + D + S, so R = R_M^T, t = -R_M^T t_M. */
TPlanePairSpec planePairForRobotMotion(const TMountedCamera& camera, const mrpt::poses::CPose3D& robotDelta,
									   const cv::Vec3d& n, double d_m, uint64_t seed);

enum class EPlaneMotion
{
	translation,  //!< forward 5-10 cm (thesis 4.8.3) in a direction within +-15 deg, no rotation
	translation_rotation,  //!< forward 5-10 cm along an arc with a yaw change of 1-3 deg either way
	rotation  //!< turning on the spot by 0.5-4 deg either way (thesis 4.8.2 i: +-1, 2, 3 deg)
};

/** The k-th random pair of a scenario (deterministic in k and seed): the
 * motion above, a plane 2-5 m ahead tilted up to 25 deg. */
TPlanePairSpec scenarioPair(const TMountedCamera& camera, EPlaneMotion motion, int k, uint64_t seed);

}  // namespace hslam::vision
