/* hslam: complete evaluation of an estimated 2D trajectory against a
 * reference: timestamp association, ATE after SE(2) alignment, and RPE for
 * consecutive poses and for fixed travelled distances. The entry point for
 * apps and the batch processor. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/absolute_trajectory_error.h>
#include <hslam/eval/relative_pose_error.h>
#include <hslam/eval/trajectory_association.h>

#include <cstddef>
#include <string>
#include <vector>

namespace hslam::eval
{
struct TEvaluationOptions
{
	/** Largest |t_estimate - t_reference| for two poses to be matched (s). */
	double max_dt_s = 0.02;
	/** Reference path lengths for RPE pairs, besides consecutive poses (m). */
	std::vector<double> rpe_distances_m = {1.0, 5.0};
	/** Names shown in reports and errors (the app passes the file paths). */
	std::string reference_label = "reference";
	std::string estimate_label = "estimate";
};

/** RPE over one family of pose pairs. */
struct TRpeResult
{
	std::string name;  //!< "consecutive", "1m", "5m", ...: also the JSON key part
	double distance_m = 0;  //!< travelled distance of the pairs; 0 for consecutive
	TRelativePoseError errors;
};

struct TTrajectoryErrors
{
	std::string reference_label, estimate_label;
	double max_dt_s = 0;
	size_t reference_poses = 0, estimate_poses = 0;
	TTimeRange reference_time, estimate_time;

	size_t matched = 0;
	size_t unmatched_reference = 0;
	size_t unmatched_estimate = 0;

	TAbsoluteTrajectoryError ate;
	/** Consecutive pairs first, then one entry per option distance. */
	std::vector<TRpeResult> rpe;
};

/** Evaluates `estimate` against `reference` (any pose order). Throws
 * std::runtime_error when fewer than 2 poses match, naming both labels and
 * their time ranges; std::invalid_argument for bad options. */
TTrajectoryErrors evaluateTrajectory(const common::TTrajectory2D& reference,
									 const common::TTrajectory2D& estimate,
									 const TEvaluationOptions& options = {});

/** Reads two TUM files (readTumFile errors pass through) and evaluates them
 * with the file paths as labels. */
TTrajectoryErrors evaluateTumFiles(const std::string& referencePath, const std::string& estimatePath,
								   TEvaluationOptions options = {});

/** Name of the RPE entry for a distance: 1.0 -> "1m", 2.5 -> "2.5m". */
std::string rpeDistanceName(double distance_m);

}  // namespace hslam::eval
