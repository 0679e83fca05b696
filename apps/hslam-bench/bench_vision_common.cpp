/* hslam-bench vision: the camera and options every part of the suite uses. */
#include "bench_vision.h"

namespace hslam::bench
{
vision::TMountedCamera benchCamera(int width, int height)
{
	vision::TCameraIntrinsicsOptions in;
	in.width_px = width;
	in.height_px = height;
	return vision::mountedCamera(in, vision::TCameraMountOptions{});
}

vision::TVisionOptions benchVisionOptions(int width)
{
	const double s = width / 640.0;
	vision::TVisionOptions o;
	o.foe.noise_floor_px *= s;
	o.flow.corner_min_distance_px *= s;
	o.cues.cluster_distance_px *= s;
	return o;
}

}  // namespace hslam::bench
