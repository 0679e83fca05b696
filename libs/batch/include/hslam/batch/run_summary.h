/* hslam: the figures of one hslam-process run, as summary.json beside its
 * outputs (read by scripts/batch-process.sh to build a table over many runs,
 * and shown at the top of report.html).
 *
 * summary.json keys (units in the names): input, output_dir, hslam_version,
 * mrpt_version, pose_method, entries, scans, scans_ignored,
 * laser_returns_inside_robot, odometry_gaps,
 * sonar_observations, tiles, sonar_corners, leg_tracks and person_tracks
 * (tracks confirmed at least once),
 * odometry_distance_scale and odometry_scale_applied ([odometry_self_calibration]'s
 * fit and whether it corrected the odometry),
 * odometry_time_offset_s (the offset in use at the end, s) and
 * odometry_time_offset_fit_s (the [odometry_timing] fit, null before any pair),
 * wall_s (whole run, outputs included), ms_per_scan (wall_s per scan),
 * input_error (null if the whole input was read), evaluated, ate_rmse_m,
 * ate_mean_m, ate_max_m, matched_poses (null without a reference),
 * warnings (array of sentences), with a reference evaluation (the
 * object hslam-evaluate --json writes), and loop_closure (null with
 * [loop_closure] enabled = false): keyframes, closures_tested,
 * closures_accepted, closures_rejected, rejected_by_reason (an object:
 * reason -> count, e.g. "low score", "ambiguous"), optimizations, backend_ms,
 * map_rerendered and ate_online_rmse_m (the online trajectory's ATE before
 * the pose graph, null without a reference). */
#pragma once

#include <hslam/batch/CBatchProcessor.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hslam::batch
{
/** The loop-closure back-end's figures. */
struct TLoopClosureSummary
{
	size_t keyframes = 0, closures_tested = 0, closures_accepted = 0, closures_rejected = 0, optimizations = 0;
	std::map<std::string, size_t> rejected_by_reason;  //!< why the rejected ones were (loop_closures.csv's reason)
	double backend_ms = 0;  //!< detection and optimisation, summed over the run
	bool map_rerendered = false;  //!< the map comes from the optimised graph
	std::optional<double> ate_online_rmse_m;  //!< trajectory_online.tum, with a reference
};

struct TRunSummary
{
	std::string input, output_dir, pose_method;
	size_t entries = 0, scans = 0, scans_ignored = 0, odometry_gaps = 0, sonar_observations = 0;
	size_t laser_returns_inside_robot = 0;  //!< [process] footprint_*: returns of the robot itself
	size_t tiles = 0, sonar_corners = 0, leg_tracks = 0, person_tracks = 0;
	size_t matches = 0, matches_failed = 0, matches_rejected = 0;
	double odometry_distance_scale = 1;  //!< fitted by [odometry_self_calibration]
	bool odometry_scale_applied = false;  //!< the fit corrected the odometry
	double odometry_heading_scale = 1;  //!< fitted heading scale (1 / Eb); 1 unless estimate_heading
	double odometry_curvature_deg_per_m = 0;  //!< fitted heading gained per metre (Ed); 0 unless estimate_heading
	bool odometry_heading_applied = false;  //!< the heading terms corrected the odometry
	/** [odometry_scale_check]: the gross scales found (1: none) and whether they are applied. */
	double odometry_gross_distance_scale = 1, odometry_gross_turn_scale = 1;
	bool odometry_gross_scale_applied = false;
	double odometry_time_offset_s = 0;  //!< [odometry_timing] offset in use at the end
	std::optional<double> odometry_time_offset_fit_s;  //!< its fit (none before a pair was scored)
	double wall_s = 0;
	double ms_per_scan = 0;  //!< wall_s * 1000 / scans (0 without scans)
	std::string input_error;  //!< empty when the whole input was read
	std::optional<eval::TTrajectoryErrors> evaluation;
	std::optional<TLoopClosureSummary> loop_closure;  //!< with [loop_closure] enabled
	std::vector<std::string> warnings;  //!< things a person should look at
};

/** Collects the figures of a finished run; `wall_s` is the run's duration. */
TRunSummary summarizeRun(const slam::CMappingPipeline& pipeline, const TBatchRequest& request, const TBatchResult& result,
						 double wall_s);

/** The summary.json text. */
std::string runSummaryToJson(const TRunSummary& summary);

/** Writes runSummaryToJson() to `path`; throws std::runtime_error naming it. */
void writeRunSummaryJson(const TRunSummary& summary, const std::string& path);

}  // namespace hslam::batch
