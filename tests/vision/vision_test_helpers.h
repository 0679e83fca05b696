/* Shared pieces of the vision tests: the thesis camera on the robot. */
#pragma once

#include <hslam/vision/synthetic_evaluation.h>

namespace hslam::vision::testing
{
inline TMountedCamera thesisCamera(int width = 640, int height = 480)
{
	TCameraIntrinsicsOptions in;
	in.width_px = width;
	in.height_px = height;
	return mountedCamera(in, TCameraMountOptions{});
}

}  // namespace hslam::vision::testing
