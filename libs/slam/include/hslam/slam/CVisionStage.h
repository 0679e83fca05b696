/* hslam: the camera branch of the mapping pipeline (thesis figure 55, 4.8).
 * Per CObservationImage (with [vision] camera_label, or any when empty):
 *     grey image -> pair with the previous image -> vision::CFlowAnalyzer
 *     (flow, rotation removal with the odometry yaw change between the two
 *     images, FOE, moving-object cues) -> one row of vision.csv
 * The yaw change comes from the pipeline's dead-reckoning pose at each image;
 * across an odometry gap it is unknown, the rotation is not removed and the
 * row says so (rotation_known = 0). Stage timings go into the pipeline's
 * timer (vision_image, vision_flow, vision_rotation, vision_foe, vision_cues).
 * Debug panels (thesis figures 172, 178-184) are kept PNG-encoded for the
 * first debug_max_images frames that are a multiple of debug_every_frames.
 *
 * INI section [vision] (config_ini/hslam-default.ini). */
#pragma once

#include <hslam/common/CStageTimer.h>
#include <hslam/dynamic/CCameraCueBuffer.h>
#include <hslam/vision/CFlowAnalyzer.h>
#include <hslam/vision/observation_image.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hslam::slam
{
struct TVisionStageOptions  //!< [vision]
{
	vision::TVisionOptions analysis;
	std::string camera_label;  //!< only images with this sensor label; empty = all
	vision::TCameraIntrinsicsOptions fallback_intrinsics;  //!< for images without camera parameters
	int debug_every_frames = 0;  //!< 0 = no debug panels
	int debug_max_images = 50;

	template <class V>
	void visit(V& v)
	{
		analysis.visit(v);
		v.text("camera_label", camera_label);
		fallback_intrinsics.visit(v);
		v.integer("debug_every_frames", debug_every_frames, 0, 1000000);
		v.integer("debug_max_images", debug_max_images, 1, 100000);
	}
};

/** One analysed image pair (vision.csv). */
struct TVisionRow
{
	size_t frame = 0;  //!< index of the second image among the used images
	double t_s = 0;
	double robot_yaw_deg = 0;  //!< odometry yaw change between the two images
	bool rotation_known = true;
	size_t corners = 0, tracks = 0, lost = 0, fb_rejected = 0;
	vision::TFoeEstimate foe;  //!< inlier vector cleared
	vision::TFoeVote vote;
	std::vector<vision::TMovingRegion> regions;
	size_t inconsistent = 0;
};

/** The moving-object cues of a row for the dynamic object filter
 * ([dynamic_objects] camera_cue_evidence): bearing ranges in the robot frame. */
std::vector<dynamic::TCameraCue> cameraCues(const TVisionRow& row);

class CVisionStage
{
   public:
	/** Loads [vision]; loads the learned model file when rotation_model =
	 * learned (throws common::config_error naming the key if it cannot). */
	explicit CVisionStage(const mrpt::config::CConfigFileBase& cfg);
	~CVisionStage();

	/** One image at the robot's dead-reckoning pose (nullopt: unknown, across an odometry gap). */
	void process(const mrpt::obs::CObservationImage& obs, const std::optional<mrpt::poses::CPose2D>& odometryPose,
				 common::CStageTimer& timer);

	const TVisionStageOptions& options() const { return m_options; }
	const std::vector<TVisionRow>& rows() const { return m_rows; }
	/** PNG-encoded debug panels with their frame index. */
	const std::vector<std::pair<size_t, std::vector<uint8_t>>>& debugImages() const { return m_debug; }
	size_t imagesIgnored() const { return m_ignored; }

   private:
	const vision::IRotationFlowModel* rotationModelFor(const vision::TMountedCamera& camera);

	TVisionStageOptions m_options;
	std::unique_ptr<vision::CLearnedRotationFlow> m_learned;
	std::unique_ptr<vision::CAnalyticRotationFlow> m_analytic;
	cv::Mat m_previous;
	std::optional<mrpt::poses::CPose2D> m_previousPose;
	size_t m_images = 0, m_ignored = 0;
	std::vector<TVisionRow> m_rows;
	std::vector<std::pair<size_t, std::vector<uint8_t>>> m_debug;
};

}  // namespace hslam::slam
