/* hslam-bench vision: the camera branch (libs/vision, thesis 4.8) on image
 * pairs with exact ground truth, against OpenCV's essential matrix on the
 * same tracks, and the camera's moving-object cues against the laser leg
 * tracks (bench_vision*.cpp). */
#pragma once

#include <hslam/vision/CFlowAnalyzer.h>
#include <hslam/vision/synthetic_evaluation.h>

#include <string>
#include <vector>

namespace hslam::bench
{
/** `hslam-bench vision`: FOE errors, rotation residuals, per-stage times and
 * the cue table (samplesDir holds rawlog_samples/camera). */
int runVisionSuite(int repetitions, const std::string& samplesDir);

/** The thesis camera (f = 800 px at 640 x 480, scaled) on its off-axis mount. */
vision::TMountedCamera benchCamera(int width, int height);
/** Vision options for an image width: the 640-pixel values (noise floor,
 * corner spacing, cue clustering) scaled by width / 640 (docs/vision.md). */
vision::TVisionOptions benchVisionOptions(int width);

/** The peer: ego-motion from the same tracks by cv::findEssentialMat (RANSAC,
 * 1 px) + cv::recoverPose, FOE = K t / t_z of the recovered translation. */
struct TEssentialFoe
{
	bool valid = false;
	cv::Point2d foe;
	int inliers = 0;
};
TEssentialFoe essentialMatrixFoe(const std::vector<vision::TFlowVector>& tracks, const cv::Matx33d& K);

/** Per-frame times (ms, best of `repetitions` per pair, mean over pairs) of
 * each stage and of the peer at one image size; printed as a table row. */
struct TTruthPair;
struct TStageTimes
{
	std::string source;  //!< "plane" or "simulator"
	int width = 0, height = 0;
	double detect_ms = 0, track_ms = 0, rotation_analytic_ms = 0, rotation_learned_ms = 0, foe_ms = 0, cues_ms = 0;
	double peer_ms = 0;
	double total_ms() const { return detect_ms + track_ms + rotation_analytic_ms + foe_ms + cues_ms; }
};
TStageTimes measureStageTimes(const std::string& source, const std::vector<TTruthPair>& pairs,
							  const vision::IRotationFlowModel& learned, int repetitions);

/** Camera cue vs laser leg tracks on a simulated sample (bench_vision_cues.cpp):
 * the batch pipeline with [dynamic_objects] camera_cue_evidence off and on.
 * Prints its table and key=value lines; returns false if the sample is missing. */
bool runVisionCuesPart(const std::string& sampleDir);

}  // namespace hslam::bench
