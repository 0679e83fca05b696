/* hslam vision: one image pair through the camera branch of thesis figure 55:
 *     corners + Lucas-Kanade flow (forward-backward checked)
 *     -> flow predicted for the robot's rotation (analytic or learned), removed
 *     -> FOE (least squares / RANSAC, and the thesis's column vote)
 *     -> moving-object cues (vectors inconsistent with the FOE, clustered)
 * Each stage is timed into a common::CStageTimer when one is given
 * (vision_flow, vision_rotation, vision_foe, vision_cues). */
#pragma once

#include <hslam/common/CStageTimer.h>
#include <hslam/vision/foe.h>
#include <hslam/vision/moving_cues.h>
#include <hslam/vision/optical_flow.h>
#include <hslam/vision/rotation_flow.h>

#include <string>
#include <vector>

namespace hslam::vision
{
struct TVisionOptions  //!< [vision]
{
	bool enabled = true;
	std::string rotation_model = "analytic";  //!< analytic | learned | none
	std::string rotation_model_file;  //!< learned: model written by hslam-vision-train (relative to the INI)
	TFlowOptions flow;
	TFoeOptions foe;
	TMovingCueOptions cues;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.choice("rotation_model", rotation_model, {"analytic", "learned", "none"});
		v.text("rotation_model_file", rotation_model_file);
		flow.visit(v);
		foe.visit(v);
		cues.visit(v);
	}
};

struct TFrameAnalysis
{
	TFlowResult flow;
	std::vector<cv::Point2f> predicted;  //!< rotation flow at each flow.vectors[i].p0
	std::vector<TFlowVector> residual;  //!< flow minus predicted (based at p0 + predicted)
	TFoeEstimate foe;
	TFoeVote vote;
	std::vector<size_t> inconsistent;  //!< indices into residual
	std::vector<TMovingRegion> regions;
};

class CFlowAnalyzer
{
   public:
	/** `rotationModel` may be null (no rotation removal); it must outlive the analyzer. */
	CFlowAnalyzer(TMountedCamera camera, const IRotationFlowModel* rotationModel, TVisionOptions options);

	/** Analyses the pair (grey 8-bit images) for a robot yaw change between them. */
	TFrameAnalysis analyze(const cv::Mat& prevGrey, const cv::Mat& currGrey, double robotYaw_rad,
						   common::CStageTimer* timer = nullptr) const;

	const TMountedCamera& camera() const { return m_camera; }
	const TVisionOptions& options() const { return m_options; }

   private:
	TMountedCamera m_camera;
	const IRotationFlowModel* m_rotation;
	TVisionOptions m_options;
};

}  // namespace hslam::vision
