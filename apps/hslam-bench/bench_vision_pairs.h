/* hslam-bench vision: image pairs with a known FOE (bench_vision_pairs.cpp). */
#pragma once

#include <hslam/vision/plane_warp.h>

#include <vector>

namespace hslam::bench
{
struct TTruthPair
{
	cv::Mat first, second;  //!< CV_8UC1
	double robot_yaw_rad = 0;
	cv::Point2d foe;  //!< true FOE in the second image
};

/** Scene of the simulated lab (relative to the worktree root). */
inline const char* kLabScene = "config_ini/sim-worlds/lab.scene";

/** Plane-warp pairs k = 0..pairs-1 of a scenario seen by `camera`. */
std::vector<TTruthPair> planePairs(const vision::TMountedCamera& camera, vision::EPlaneMotion motion, int pairs,
								   uint64_t seed);

/** Simulator frames of the static lab from random poses, forward 5-10 cm,
 * with a yaw change of 1-3 deg either way when `rotate`. */
std::vector<TTruthPair> renderedPairs(int width, int height, bool rotate, int pairs, uint64_t seed);

}  // namespace hslam::bench
