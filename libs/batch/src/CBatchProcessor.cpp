#include <hslam/common/CProgressBar.h>
#include <hslam/common/options_io.h>
#include <hslam/common/output_folder.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/eval/evaluation_json.h>
#include <hslam/eval/evaluation_table.h>
#include <hslam/eval/scan_consistency.h>
#include <hslam/batch/CBatchProcessor.h>
#include <hslam/slam/loop_closure_outputs.h>
#include <hslam/slam/mapping_config.h>
#include <hslam/slam/pose_plots.h>
#include <hslam/batch/run_report.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <fstream>

namespace hslam::batch
{
namespace
{
/** The odometry self-calibration's fit, as the model and as UMBmark factors. */
void printOdometryCalibration(const calib::COdometrySelfCalibration& calibration, std::ostream& out)
{
	if (!calibration.enabled()) return;
	const auto& st = calibration.state();
	out << "Odometry self-calibration ([odometry_self_calibration]): " << st.intervals << " intervals over "
		<< st.travel_m << " m (" << st.outliers << " outliers); distance x" << st.distance_scale << ", heading x"
		<< st.heading_scale << ", curvature " << st.curvature_bias_rad_per_m * 180.0 / M_PI
		<< " deg/m = c_L " << st.correction.left_factor << ", c_R " << st.correction.right_factor << ", Eb "
		<< st.correction.wheelbase_ratio
		<< (st.distance_applied ? "; distance applied" : "; distance not applied (within the front-end's own bias)")
		<< (st.heading_applied ? "; heading applied" : "") << "\n";
}
/** Odometry found off by a gross factor ([odometry_scale_check]), if any. */
void printOdometryScaleCheck(const calib::COdometryScaleCheck& check, std::ostream& out)
{
	const auto gross = [&](const calib::TOdometryScaleFit& f) {
		return f.applied || std::abs(std::log(f.median_ratio)) >= std::log(check.options().min_scale_factor);
	};
	if (!check.options().enabled || (!gross(check.distance()) && !gross(check.turn()))) return;
	const auto describe = [&](const char* what, const calib::TOdometryScaleFit& f) {
		out << f.median_ratio << " x the matched " << what << " (" << f.samples << " samples"
			<< (f.applied ? "; scale " + std::to_string(f.scale) : "") << ")";
	};
	out << "Odometry scale check ([odometry_scale_check]): the readings are ";
	describe("distance", check.distance());
	out << " and ";
	describe("turn", check.turn());
	out << "; the readings' finest turn " << check.turnStep_rad() * 180.0 / M_PI << " deg"
		<< (!check.applying()		   ? "; not rescaled (both quantities must be judged, and fine enough once rescaled)"
			: check.options().rescale ? "; rescaled"
									  : "; not rescaled ([odometry_scale_check] rescale = false)")
		<< "\n";
}
/** The odometry time offset in use and its fit ([odometry_timing]). */
void printOdometryTiming(const slam::CMappingPipeline& pipeline, std::ostream& out)
{
	const auto fit = pipeline.odometryTimeOffset().estimate(pipeline.odometryOffsetInUse_s());
	if (pipeline.odometryOffsetInUse_s() == 0 && !fit) return;
	out << "Odometry time offset ([odometry_timing]): " << pipeline.odometryOffsetInUse_s() << " s in use";
	if (fit)
		out << "; fit " << fit->offset_s << " s over " << fit->pairs << " match pairs ("
			<< fit->rotation_rad * 180.0 / M_PI << " deg of rotation, cost " << fit->cost_ratio
			<< " of the offset in use, " << fit->readings_per_pair << " odometry readings per pair)";
	out << "\n";
}
}  // namespace

CBatchProcessor::CBatchProcessor(TBatchRequest request, std::ostream& out, std::ostream& err)
	: m_request(std::move(request)), m_out(out), m_err(err)
{
}

TBatchResult CBatchProcessor::run()
{
	const auto started = std::chrono::steady_clock::now();
	auto config = slam::TMappingConfig::fromConfig(m_request.config_file, m_request.overrides);
	const slam::TOutputOptions& outputOptions = config.output;
	common::COutputFolder folder(m_request.output_dir, m_request.overwrite);  // lock, refuse foreign, clean stale
	TBatchResult result;
	const auto pipelinePtr = processRawlog(config, result);
	slam::CMappingPipeline& pipeline = *pipelinePtr;
	if (const auto* loop = pipeline.loopClosureStage(); loop && m_request.show_progress)
		if (const size_t queued = loop->queuedKeyframes(); queued > 0)
			m_err << "Loop closure: finishing " << queued << " queued keyframe(s)\n";
	pipeline.finish();  // waits for the loop-closure back-end; map from the optimised graph, if any
	result.counters = pipeline.counters();
	result.files_written = slam::writeMappingOutputs(pipeline, outputOptions, m_request.output_dir);
	writeEffectiveConfig(pipeline, outputOptions);
	printSummary(pipeline, result);
	if (!m_request.ground_truth_tum.empty()) evaluate(pipeline, result);
	const std::chrono::duration<double> wall_s = std::chrono::steady_clock::now() - started;
	for (auto& f : writeRunReport(pipeline, m_request, result, wall_s.count())) result.files_written.push_back(f);
	m_out << "\nReport: " << m_request.output_dir << "/report.html (figures: summary.json)\n";
	folder.finish();
	return result;
}

std::unique_ptr<slam::CMappingPipeline> CBatchProcessor::makePipeline(const slam::TMappingConfig& config)
{
	auto pipeline = std::make_unique<slam::CMappingPipeline>(config.ini);
	if (config.output.write_sensor_maps) pipeline->keepSensorMaps();
	if (config.output.dynamic_debug_images)
		pipeline->keepDynamicDebugFrames(static_cast<size_t>(config.output.dynamic_debug_max_images));
	addDebugFrameWriter(*pipeline, config.output.debug_frames_every);
	return pipeline;
}

std::unique_ptr<slam::CMappingPipeline> CBatchProcessor::processRawlog(slam::TMappingConfig& config,
																	   TBatchResult& result)
{
	auto pipeline = makePipeline(config);
	readRawlog(*pipeline, result);
	const auto found = secondPassOverrides(*pipeline);
	if (found.empty()) return pipeline;
	auto overrides = m_request.overrides;
	overrides.insert(overrides.end(), found.begin(), found.end());
	config = slam::TMappingConfig::fromConfig(m_request.config_file, overrides);
	result = TBatchResult();
	pipeline.reset();  // the first pass's memory, before the second's
	pipeline = makePipeline(config);
	readRawlog(*pipeline, result);
	return pipeline;
}

std::vector<std::string> CBatchProcessor::secondPassOverrides(const slam::CMappingPipeline& pipeline)
{
	std::vector<std::string> overrides;
	if (pipeline.odometryTiming().second_pass && pipeline.counters().odometry_offset_changes > 0)
	{
		// floor sample with odometry 0.3 s late: fitted after the first corner,
		// whose heading error stayed (docs/pose-estimation.md)
		const double offset_s = pipeline.odometryOffsetInUse_s();
		m_out << "Odometry time offset fitted during the run: " << offset_s
			  << " s ([odometry_timing]); second pass from the start with it\n";
		overrides.push_back("odometry_timing.offset_s=" + std::to_string(offset_s));
		overrides.push_back("odometry_timing.estimate_offset=false");
	}
	const auto& check = pipeline.odometryScaleCheck();
	if (check.options().rescale && check.options().second_pass && check.applying())
	{
		// aces with every reading at 1 %: the scans before the scale was
		// found had already bent the map (ATE 23.3 m; odometry 19.7)
		const double distance = check.scaleInUse().x, turn = check.scaleInUse().y;
		m_out << "Odometry found off by a gross factor ([odometry_scale_check]): second pass from the start with it"
			  << " rescaled by " << distance << " (distance), " << turn << " (turn)\n";
		overrides.push_back("odometry_scale_check.distance_scale=" + std::to_string(distance));
		overrides.push_back("odometry_scale_check.turn_scale=" + std::to_string(turn));
	}
	return overrides;
}

void CBatchProcessor::readRawlog(slam::CMappingPipeline& pipeline, TBatchResult& result)
{
	const size_t total = m_request.show_progress ? io::CRawlogReader::countEntries(m_request.input_rawlog) : 0;
	io::CRawlogReader reader(m_request.input_rawlog);
	common::CProgressBar progress(m_err, common::CProgressBar::stderrIsTerminal(), total, "entries");
	io::TRawlogEntry entry;
	try
	{
		for (;;)
		{
			{
				common::CStageTimer::CScope t(pipeline.timer(), "read");
				if (!reader.next(entry)) break;
			}
			pipeline.processEntry(entry);
			if (m_request.show_progress) progress.update(reader.entriesRead());
		}
	}
	catch (const io::rawlog_error& e)
	{
		result.input_error = e.what();
	}
	// Corrupt parts skipped by resynchronisation: reported like a fault.
	if (!reader.problems().empty())
		result.input_error = reader.problemSummary() + (result.input_error.empty() ? "" : "\n" + result.input_error);
	if (m_request.show_progress) progress.finish();
}

void CBatchProcessor::addDebugFrameWriter(slam::CMappingPipeline& pipeline, int every)
{
	if (every <= 0) return;
	const std::string dir = m_request.output_dir + "/frames";
	std::filesystem::create_directories(dir);
	auto counter = std::make_shared<size_t>(0);
	pipeline.addEstimateObserver([dir, every, counter](const mrpt::obs::CObservation2DRangeScan& scan,
													   const slam::TPoseEstimate& estimate) {
		const size_t index = (*counter)++;
		if (index % static_cast<size_t>(every) != 0) return;
		char name[32];
		std::snprintf(name, sizeof(name), "/frame_%06zu.png", index);
		if (!renderScanDebugImage(scan, estimate).saveToFile(dir + name))
			throw std::runtime_error(dir + name + ": cannot write image");
	});
}

void CBatchProcessor::writeEffectiveConfig(const slam::CMappingPipeline& pipeline, const slam::TOutputOptions& outputOptions)
{
	mrpt::config::CConfigFileMemory effective;
	pipeline.saveOptions(effective);
	common::saveOptions(outputOptions, effective, "output");
	const std::string path = m_request.output_dir + "/config_used.ini";
	common::writeTextFileAtomically(
		path, "; Effective configuration of this run: every key the run read, defaults and --set overrides\n"
			  "; included, file paths absolute. hslam-process -c config_used.ini reproduces the run.\n" +
				  effective.getContent());
}

void CBatchProcessor::printSummary(const slam::CMappingPipeline& pipeline, const TBatchResult& result)
{
	const auto& c = result.counters;
	m_out << "Input:            " << m_request.input_rawlog << "\n"
		  << "Pose estimation:  " << pipeline.poseEstimatorName() << "\n"
		  << "Entries read:     " << c.entries << "\n"
		  << "Laser scans used: " << c.laser_scans << " (ignored by label: " << c.laser_scans_ignored << ")\n"
		  << "Odometry:         " << c.odometry_readings << " readings, " << c.odometry_gaps << " gaps\n"
		  << "Sonar rings used: " << c.sonar_observations << " (ignored: " << c.sonar_observations_ignored
		  << "), readings inserted into the grid: " << c.sonar_readings_inserted
		  << (pipeline.sonarStage().mappingOptions().enabled ? "" : " ([sonar_model] enabled = false)") << "\n";
	if (pipeline.sonarStage().reportsCorners())
		m_out << "TBF sonar corners: " << pipeline.sonarStage().corners().size() << " with support >= "
			  << pipeline.sonarStage().tbfOptions().min_support << "\n";
	m_out << "Tiles:            " << pipeline.grid().tileCount() << " (" << pipeline.grid().memoryBytes() / 1024
		  << " KiB)\n";
	printMatchSummary(pipeline);
	printOdometryScaleCheck(pipeline.odometryScaleCheck(), m_out);
	printOdometryCalibration(pipeline.odometryCalibration(), m_out);
	printOdometryTiming(pipeline, m_out);
	if (pipeline.loopClosureStage())
	{
		printLoopClosureTiming(*pipeline.loopClosureStage(), m_out);
		m_out << "  map re-rendered from the optimised graph: " << (pipeline.mapRerendered() ? "yes" : "no") << "\n";
	}
	m_out << "\nTiming per call:\n";
	pipeline.timer().printTable(m_out);
	m_out << "\nResults written to " << m_request.output_dir << "/ (map.png, tiles/, map.gridmap.gz, "
		  << "trajectory.tum, odometry.tum, timing.csv, config_used.ini"
		  << (pipeline.dynamicFilter() ? ", tracks.csv" : "")
		  << (pipeline.sonarStage().reportsCorners() ? ", sonar_corners.csv, map_sonar_corners.png" : "")
		  << (pipeline.laserOnlyMap() ? ", map_laser_only.png" : "")
		  << (pipeline.sonarOnlyMap() ? ", map_sonar_only.png" : "") << ")\n";
	if (!result.input_error.empty())
		m_err << "error: " << result.input_error << "\n"
			  << "       results for the " << c.entries << " entries read before the fault were written.\n";
}

void CBatchProcessor::printMatchSummary(const slam::CMappingPipeline& pipeline)
{
	std::map<std::string, std::array<size_t, 4>> byMethod;  // good, weak, failed, rejected
	size_t matched = 0;
	for (const auto& [t, e] : pipeline.estimates())
	{
		if (!e.matched) continue;
		++matched;
		auto& counts = byMethod[e.match_method.empty() ? "none" : e.match_method];
		++counts[static_cast<size_t>(e.match_quality)];
		if (e.match_quality != matching::EMatchQuality::failed && !e.match_accepted) ++counts[3];
	}
	if (matched == 0) return;
	m_out << "Scan matches:     " << matched << " of " << pipeline.estimates().size() << " scans\n";
	for (const auto& [method, c] : byMethod)
		m_out << "  " << method << ": " << c[0] << " good, " << c[1] << " weak, " << c[2] << " failed, " << c[3]
			  << " rejected by the UKF gate\n";
}

std::optional<eval::TScanConsistency> CBatchProcessor::scanConsistency(const slam::CMappingPipeline& pipeline,
																	   const common::TTrajectory2D& reference,
																	   const TBatchResult& result)
{
	// How well the reference and the estimate explain the scans (the
	// reference's own slips, docs/pose-estimation.md). Only over a rawlog read
	// to its end, and for one laser.
	if (!result.input_error.empty()) return std::nullopt;
	try
	{
		eval::TScanConsistencyOptions o;
		const auto scans = eval::readScanPoints(m_request.input_rawlog, pipeline.processOptions().laser_label, o.max_range_m);
		auto c = eval::compareScanConsistency(scans, reference, pipeline.finalTrajectory(), o);
		eval::printScanConsistency(m_out, c, 5);
		return c;
	}
	catch (const std::exception& e)
	{
		m_out << "\nScan consistency not measured: " << e.what() << "\n";
		return std::nullopt;
	}
}

void CBatchProcessor::evaluate(const slam::CMappingPipeline& pipeline, TBatchResult& result)
{
	const auto reference = common::readTumFile(m_request.ground_truth_tum);
	eval::TEvaluationOptions options;
	options.reference_label = m_request.ground_truth_tum;
	options.estimate_label = m_request.output_dir + "/trajectory.tum";
	const auto errors = eval::evaluateTrajectory(reference, pipeline.finalTrajectory(), options);
	m_out << "\nEvaluation against " << m_request.ground_truth_tum << ":\n";
	eval::printEvaluation(m_out, errors);
	const auto consistency = scanConsistency(pipeline, reference, result);
	eval::writeEvaluationJson(m_request.output_dir + "/evaluation.json", errors, consistency ? &*consistency : nullptr);
	if (pipeline.loopClosureStage())  // the online (filtered) trajectory too, for before/after
	{
		options.estimate_label = m_request.output_dir + "/trajectory_online.tum";
		const auto online = eval::evaluateTrajectory(reference, pipeline.trajectory(), options);
		m_out << "\nOnline (before the pose graph):\n";
		eval::printEvaluation(m_out, online);
		eval::writeEvaluationJson(m_request.output_dir + "/evaluation_online.json", online);
		result.evaluation_online = online;
	}
	result.evaluated = true;
	result.evaluation = errors;
}

}  // namespace hslam::batch
