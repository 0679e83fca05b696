/* hslam vision: what the camera branch needs from an MRPT camera observation. */
#pragma once

#include <hslam/vision/camera_geometry.h>
#include <mrpt/obs/CObservationImage.h>
#include <opencv2/core.hpp>

namespace hslam::vision
{
/** The image as 8-bit grey (a copy; colour is converted). Throws
 * std::runtime_error for an empty image. */
cv::Mat greyImageOf(const mrpt::obs::CObservationImage& obs);

/** Intrinsics (cameraParams) and camera pose on the robot (cameraPose); an
 * observation without intrinsics (fx = 0) gets `fallback` scaled to its size. */
TMountedCamera mountedCameraOf(const mrpt::obs::CObservationImage& obs, const mrpt::img::TCamera& fallback);

}  // namespace hslam::vision
