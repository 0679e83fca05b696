#include "training_pairs.h"

#include <hslam/io/CRawlogReader.h>
#include <hslam/vision/observation_image.h>
#include <hslam/vision/synthetic_evaluation.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <optional>
#include <stdexcept>

namespace hslam::vision_train
{
vision::TFlowOptions flowOptionsFor(int width)
{
	vision::TFlowOptions o;
	o.corner_min_distance_px *= width / 640.0;
	return o;
}

namespace
{
struct TImageAtPose
{
	cv::Mat grey;
	std::optional<mrpt::poses::CPose2D> odometry;
};

/** Reads the rawlog, calling `onImage` per used image with the odometry pose then. */
template <class F>
void forEachImage(const std::string& path, const std::string& label, F&& onImage)
{
	io::CRawlogReader reader(path);
	std::optional<mrpt::poses::CPose2D> odometry;
	const auto observe = [&](const mrpt::obs::CObservation::Ptr& obs)
	{
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs)) odometry = odo->odometry;
		if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(obs);
			img && (label.empty() || img->sensorLabel == label))
			onImage(*img, odometry);
	};
	for (io::TRawlogEntry e; reader.next(e);)
	{
		if (e.actions)
			if (auto mv = e.actions->getBestMovementEstimation())
				odometry = odometry.value_or(mrpt::poses::CPose2D()) + mv->poseChange->getMeanVal();
		if (e.frame)
			for (const auto& obs : *e.frame) observe(obs);
		if (e.observation) observe(e.observation);
	}
}

std::vector<vision::TRotationSample> samplesOfPair(const cv::Mat& a, const cv::Mat& b, double yaw_rad)
{
	std::vector<vision::TRotationSample> out;
	for (const auto& f : vision::trackFeatures(a, b, flowOptionsFor(a.cols)).vectors)
		out.push_back({f.p0, f.flow(), yaw_rad});
	return out;
}
}  // namespace

TPairSet pairsFromRawlog(const std::string& path, const TVisionTrainOptions& o)
{
	TPairSet set;
	std::optional<TImageAtPose> previous;
	forEachImage(path, o.camera_label,
				 [&](const mrpt::obs::CObservationImage& img, const std::optional<mrpt::poses::CPose2D>& odometry)
				 {
					 TImageAtPose now{vision::greyImageOf(img), odometry};
					 if (set.images++ == 0)
					 {
						 set.width = now.grey.cols, set.height = now.grey.rows;
						 set.camera = vision::mountedCameraOf(img, vision::cameraFromOptions({}));
					 }
					 else if (now.grey.cols != set.width || now.grey.rows != set.height)
						 throw std::runtime_error(path + ": image " + std::to_string(set.images) + " is " +
												  std::to_string(now.grey.cols) + " x " + std::to_string(now.grey.rows) +
												  ", the first was " + std::to_string(set.width) + " x " +
												  std::to_string(set.height));
					 if (!odometry) ++set.no_odometry;
					 if (previous && previous->odometry && odometry)
					 {
						 const mrpt::poses::CPose2D d = *odometry - *previous->odometry;
						 const double yaw = mrpt::math::wrapToPi(odometry->phi() - previous->odometry->phi());
						 if (std::abs(yaw) * 180.0 / M_PI >= o.min_turn_deg && d.norm() <= o.max_travel_m)
							 set.pairs.push_back(samplesOfPair(previous->grey, now.grey, yaw));
						 else
							 ++set.not_turning;
					 }
					 previous = std::move(now);
				 });
	if (set.images == 0)
		throw std::runtime_error(path + ": no CObservationImage" +
								 (o.camera_label.empty() ? std::string() : " with label '" + o.camera_label + "'"));
	if (set.no_odometry == set.images)
		throw std::runtime_error(path + ": no odometry (CObservationOdometry or CActionRobotMovement2D) before any image");
	return set;
}

TPairSet syntheticPairs(const vision::TMountedCamera& camera, int count, uint64_t seed)
{
	TPairSet set;
	set.camera = camera;
	set.width = static_cast<int>(camera.intrinsics.ncols);
	set.height = static_cast<int>(camera.intrinsics.nrows);
	const auto flow = flowOptionsFor(set.width);
	for (int k = 0; k < count; ++k)
	{
		set.pairs.push_back(vision::rotationSamplesOnScenario(camera, k, k + 1, seed, flow));
		set.checked.push_back(vision::rotationSamplesOnScenario(camera, k, k + 1, seed, flow, 2.0, &set.tracker_failures));
	}
	set.images = 2 * static_cast<size_t>(count);
	return set;
}

}  // namespace hslam::vision_train
