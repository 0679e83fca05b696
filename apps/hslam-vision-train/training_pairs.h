/* hslam-vision-train: tracked corners of image pairs taken while the robot
 * turns on the spot, labelled with the robot's rotation (thesis 4.8.2 i-ii:
 * pairs at +-1, 2, 3 deg), from a rawlog or from plane-warp pairs. */
#pragma once

#include "vision_train_options.h"

#include <hslam/vision/camera_geometry.h>

#include <string>
#include <vector>

namespace hslam::vision_train
{
struct TPairSet
{
	std::vector<std::vector<vision::TRotationSample>> pairs;  //!< the tracks of each used pair
	/** Synthetic pairs only: the tracks within 2 px of the true motion (tracker
	 * failures of 50+ px are not errors of a rotation model); the held-out
	 * figure uses these. Empty for a rawlog (no truth). */
	std::vector<std::vector<vision::TRotationSample>> checked;
	size_t tracker_failures = 0;  //!< synthetic: tracks left out of `checked`
	int width = 0, height = 0;
	vision::TMountedCamera camera;  //!< of the images (for the analytic comparison)
	size_t images = 0;  //!< images read
	size_t not_turning = 0;  //!< consecutive pairs left out (turn too small or travel too long)
	size_t no_odometry = 0;  //!< images without an odometry reading before them
};

/** Flow options for an image width: corner spacing scaled from 640 px. */
vision::TFlowOptions flowOptionsFor(int width);

/** Consecutive images of `path` (CObservationImage, label `camera_label` if
 * set) with the odometry pose at each (the latest CObservationOdometry, or
 * the sum of CActionRobotMovement2D), pairs with a turn of at least
 * min_turn_deg and a travel of at most max_travel_m. Throws
 * std::runtime_error naming the file and what is missing. */
TPairSet pairsFromRawlog(const std::string& path, const TVisionTrainOptions& options);

/** `count` plane-warp turns on the spot (vision::scenarioPair rotation, 0.5-4 deg either way). */
TPairSet syntheticPairs(const vision::TMountedCamera& camera, int count, uint64_t seed);

}  // namespace hslam::vision_train
