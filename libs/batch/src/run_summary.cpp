#include <hslam/common/output_folder.h>
#include <hslam/common/json_text.h>
#include <hslam/common/version.h>
#include <hslam/eval/evaluation_json.h>
#include <hslam/batch/run_summary.h>
#include <hslam/slam/loop_closure_outputs.h>

#include <cmath>

#include <fstream>
#include <set>
#include <stdexcept>
#include <utility>

namespace hslam::batch
{
namespace
{
using common::jsonNumber;
using common::jsonString;

void countMatches(const slam::CMappingPipeline& pipeline, TRunSummary& s)
{
	for (const auto& [t, e] : pipeline.estimates())
	{
		if (!e.matched) continue;
		++s.matches;
		if (e.match_quality == matching::EMatchQuality::failed) ++s.matches_failed;
		else if (!e.match_accepted) ++s.matches_rejected;
	}
}

void countTracks(const slam::CMappingPipeline& pipeline, TRunSummary& s)
{
	std::set<int> legs, persons;
	for (const auto& row : pipeline.trackRows())
		if (row.track.state != dynamic::ETrackState::tentative)  // confirmed at least once
			(std::string(row.kind) == "person" ? persons : legs).insert(row.track.id);
	s.leg_tracks = legs.size();
	s.person_tracks = persons.size();
}

std::optional<TLoopClosureSummary> summarizeLoopClosure(const slam::CMappingPipeline& pipeline, const TBatchResult& result)
{
	const auto* stage = pipeline.loopClosureStage();
	if (!stage) return std::nullopt;
	const auto& t = stage->backend().timing();
	TLoopClosureSummary s;
	s.keyframes = t.keyframes;
	s.closures_tested = t.candidates_tested;
	s.closures_accepted = t.closures_accepted;
	s.rejected_by_reason = slam::rejectedClosuresByReason(*stage);
	for (const auto& [reason, n] : s.rejected_by_reason) s.closures_rejected += n;
	s.optimizations = t.optimizations;
	s.backend_ms = t.total_ms;
	s.map_rerendered = pipeline.mapRerendered();
	if (result.evaluation_online && !result.evaluation_online->ate.position_m.empty())
		s.ate_online_rmse_m = result.evaluation_online->ate.position_m.rmse;
	return s;
}

std::string reasonsJson(const std::map<std::string, size_t>& counts)
{
	std::string out = "{";
	for (const auto& [reason, n] : counts) out += (out.size() > 1 ? ", " : "") + jsonString(reason) + ": " + std::to_string(n);
	return out + "}";
}

std::string loopClosureJson(const std::optional<TLoopClosureSummary>& l)
{
	if (!l) return "null";
	return "{\"keyframes\": " + std::to_string(l->keyframes) + ", \"closures_tested\": " +
		   std::to_string(l->closures_tested) + ", \"closures_accepted\": " + std::to_string(l->closures_accepted) +
		   ", \"closures_rejected\": " + std::to_string(l->closures_rejected) +
		   ", \"rejected_by_reason\": " + reasonsJson(l->rejected_by_reason) +
		   ", \"optimizations\": " + std::to_string(l->optimizations) +
		   ", \"backend_ms\": " + jsonNumber(l->backend_ms, "%.1f") +
		   ", \"map_rerendered\": " + (l->map_rerendered ? "true" : "false") + ", \"ate_online_rmse_m\": " +
		   (l->ate_online_rmse_m ? jsonNumber(*l->ate_online_rmse_m) : "null") + "}";
}

void addWarnings(TRunSummary& s)
{
	auto& w = s.warnings;
	if (!s.input_error.empty())
		w.push_back("input fault: " + s.input_error + "; the results cover the " + std::to_string(s.entries) +
					" entries read before it");
	if (s.scans == 0) w.push_back("no laser scan was used (see [process] laser_label)");
	if (s.scans_ignored > 0)
		w.push_back(std::to_string(s.scans_ignored) + " laser scans ignored: another sensor label");
	if (s.laser_returns_inside_robot > 0)
		w.push_back(std::to_string(s.laser_returns_inside_robot) +
					" laser returns inside the robot's footprint dropped (see [process] footprint_*)");
	if (s.odometry_gaps > 0) w.push_back(std::to_string(s.odometry_gaps) + " odometry gaps (motion unknown)");
	if (s.matches_failed > 0)
		w.push_back(std::to_string(s.matches_failed) + " of " + std::to_string(s.matches) + " scan matches failed");
	if (s.matches_rejected > 0)
		w.push_back(std::to_string(s.matches_rejected) + " scan matches rejected by the UKF gate");
	if (s.evaluation && s.evaluation->unmatched_estimate > 0)
		w.push_back(std::to_string(s.evaluation->unmatched_estimate) +
					" estimated poses without a reference pose within max_dt_s");
}
}  // namespace

TRunSummary summarizeRun(const slam::CMappingPipeline& pipeline, const TBatchRequest& request, const TBatchResult& result,
						 double wall_s)
{
	TRunSummary s;
	const auto& c = result.counters;
	s.input = request.input_rawlog;
	s.output_dir = request.output_dir;
	s.pose_method = pipeline.poseEstimatorName();
	s.entries = c.entries;
	s.scans = c.laser_scans;
	s.scans_ignored = c.laser_scans_ignored;
	s.laser_returns_inside_robot = c.laser_returns_inside_robot;
	s.odometry_gaps = c.odometry_gaps;
	s.sonar_observations = c.sonar_observations;
	s.tiles = pipeline.grid().tileCount();
	s.sonar_corners = pipeline.sonarStage().corners().size();
	countMatches(pipeline, s);
	countTracks(pipeline, s);
	s.odometry_distance_scale = pipeline.odometryCalibration().state().distance_scale;
	s.odometry_scale_applied = pipeline.odometryCalibration().state().distance_applied;
	s.odometry_heading_scale = pipeline.odometryCalibration().state().heading_scale;
	s.odometry_curvature_deg_per_m = pipeline.odometryCalibration().state().curvature_bias_rad_per_m * 180.0 / M_PI;
	s.odometry_heading_applied = pipeline.odometryCalibration().state().heading_applied;
	const auto& gross = pipeline.odometryScaleCheck();
	s.odometry_gross_distance_scale = gross.distance().scale, s.odometry_gross_turn_scale = gross.turn().scale;
	s.odometry_gross_scale_applied = gross.applying();
	s.odometry_time_offset_s = pipeline.odometryOffsetInUse_s();
	if (const auto fit = pipeline.odometryTimeOffset().estimate(s.odometry_time_offset_s))
		s.odometry_time_offset_fit_s = fit->offset_s;
	s.wall_s = wall_s;
	s.ms_per_scan = s.scans > 0 ? wall_s * 1000.0 / static_cast<double>(s.scans) : 0.0;
	s.input_error = result.input_error;
	s.evaluation = result.evaluation;
	s.loop_closure = summarizeLoopClosure(pipeline, result);
	addWarnings(s);
	return s;
}

std::string runSummaryToJson(const TRunSummary& s)
{
	const bool evaluated = s.evaluation.has_value();
	const auto ate = [&](double eval::TErrorStats::*field) {
		return evaluated && !s.evaluation->ate.position_m.empty() ? jsonNumber(s.evaluation->ate.position_m.*field)
																	: std::string("null");
	};
	const std::vector<std::pair<std::string, std::string>> fields = {
		{"input", jsonString(s.input)},
		{"output_dir", jsonString(s.output_dir)},
		{"hslam_version", jsonString(common::projectVersion())},
		{"mrpt_version", jsonString(common::mrptBuildVersion())},
		{"pose_method", jsonString(s.pose_method)},
		{"entries", std::to_string(s.entries)},
		{"scans", std::to_string(s.scans)},
		{"scans_ignored", std::to_string(s.scans_ignored)},
		{"laser_returns_inside_robot", std::to_string(s.laser_returns_inside_robot)},
		{"odometry_gaps", std::to_string(s.odometry_gaps)},
		{"sonar_observations", std::to_string(s.sonar_observations)},
		{"tiles", std::to_string(s.tiles)},
		{"sonar_corners", std::to_string(s.sonar_corners)},
		{"leg_tracks", std::to_string(s.leg_tracks)},
		{"person_tracks", std::to_string(s.person_tracks)},
		{"odometry_distance_scale", jsonNumber(s.odometry_distance_scale, "%.5f")},
		{"odometry_scale_applied", s.odometry_scale_applied ? "true" : "false"},
		{"odometry_heading_scale", jsonNumber(s.odometry_heading_scale, "%.5f")},
		{"odometry_curvature_deg_per_m", jsonNumber(s.odometry_curvature_deg_per_m, "%.4f")},
		{"odometry_heading_applied", s.odometry_heading_applied ? "true" : "false"},
		{"odometry_gross_distance_scale", jsonNumber(s.odometry_gross_distance_scale, "%.4g")},
		{"odometry_gross_turn_scale", jsonNumber(s.odometry_gross_turn_scale, "%.4g")},
		{"odometry_gross_scale_applied", s.odometry_gross_scale_applied ? "true" : "false"},
		{"odometry_time_offset_s", jsonNumber(s.odometry_time_offset_s, "%.3f")},
		{"odometry_time_offset_fit_s",
		 s.odometry_time_offset_fit_s ? jsonNumber(*s.odometry_time_offset_fit_s, "%.3f") : "null"},
		{"wall_s", jsonNumber(s.wall_s, "%.3f")},
		{"ms_per_scan", jsonNumber(s.ms_per_scan, "%.3f")},
		{"input_error", s.input_error.empty() ? "null" : jsonString(s.input_error)},
		{"evaluated", evaluated ? "true" : "false"},
		{"ate_rmse_m", ate(&eval::TErrorStats::rmse)},
		{"ate_mean_m", ate(&eval::TErrorStats::mean)},
		{"ate_max_m", ate(&eval::TErrorStats::max)},
		{"matched_poses", evaluated ? std::to_string(s.evaluation->matched) : "null"},
		{"warnings", common::jsonStringArray(s.warnings)},
		{"evaluation", evaluated ? eval::evaluationToJson(*s.evaluation) : "null"},
		{"loop_closure", loopClosureJson(s.loop_closure)}};
	std::string out = "{\n";
	for (size_t i = 0; i < fields.size(); ++i)
		out += "  " + jsonString(fields[i].first) + ": " + fields[i].second + (i + 1 < fields.size() ? ",\n" : "\n");
	return out + "}\n";
}

void writeRunSummaryJson(const TRunSummary& summary, const std::string& path)
{
	common::writeTextFileAtomically(path, runSummaryToJson(summary));
}

}  // namespace hslam::batch
