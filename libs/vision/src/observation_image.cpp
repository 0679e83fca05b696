#include <hslam/vision/observation_image.h>

#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace hslam::vision
{
cv::Mat greyImageOf(const mrpt::obs::CObservationImage& obs)
{
	const mrpt::img::CImage& img = obs.image;
	if (img.isEmpty() || img.getWidth() == 0)
		throw std::runtime_error("camera observation '" + obs.sensorLabel + "' has an empty image");
	const cv::Mat src = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	cv::Mat grey;
	if (src.channels() == 3)
		cv::cvtColor(src, grey, cv::COLOR_BGR2GRAY);
	else if (src.channels() == 4)
		cv::cvtColor(src, grey, cv::COLOR_BGRA2GRAY);
	else
		grey = src.clone();
	if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);
	return grey;
}

TMountedCamera mountedCameraOf(const mrpt::obs::CObservationImage& obs, const mrpt::img::TCamera& fallback)
{
	TMountedCamera cam;
	cam.sensorPose = obs.cameraPose;
	cam.intrinsics = obs.cameraParams;
	if (cam.intrinsics.fx() <= 0)
	{
		cam.intrinsics = fallback;
		cam.intrinsics.scaleToResolution(static_cast<unsigned>(obs.image.getWidth()),
										 static_cast<unsigned>(obs.image.getHeight()));
	}
	return cam;
}

}  // namespace hslam::vision
