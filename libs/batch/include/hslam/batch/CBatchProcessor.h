/* hslam: the batch mapping job behind `hslam-process`: reads a rawlog
 * through the mapping pipeline with a progress bar, writes the outputs (see
 * batch_outputs.h), and optionally evaluates the trajectory against a
 * reference (summary.json and report.html last, see run_report.h). A fault in the input (corrupt or truncated rawlog) stops the
 * reading, but everything processed before it is still written. */
#pragma once

#include <hslam/eval/scan_consistency.h>
#include <optional>

#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/slam/mapping_config.h>
#include <hslam/slam/batch_outputs.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace hslam::batch
{
struct TBatchRequest
{
	std::string config_file;  //!< INI file (may be empty: all defaults)
	std::vector<std::string> overrides;  //!< "SECTION.KEY=VALUE"
	std::string input_rawlog;
	std::string output_dir;
	std::string ground_truth_tum;  //!< optional reference trajectory
	bool show_progress = true;
	bool overwrite = false;  //!< write into a non-empty folder not made by hslam (common::COutputFolder)
};

struct TBatchResult
{
	slam::TPipelineCounters counters;
	std::string input_error;  //!< non-empty if reading stopped at a fault
	std::vector<std::string> files_written;
	bool evaluated = false;
	std::optional<eval::TTrajectoryErrors> evaluation;  //!< with a ground truth
	std::optional<eval::TTrajectoryErrors> evaluation_online;  //!< the same, before the pose graph
};

class CBatchProcessor
{
   public:
	/** `out` gets the summary, `err` the progress bar and error messages. */
	CBatchProcessor(TBatchRequest request, std::ostream& out, std::ostream& err);

	/** Runs the whole job. The configuration is read by
	 * slam::TMappingConfig::fromConfig (mapping_config.h); its errors throw
	 * (common::config_error);
	 * input faults are reported in the result after writing the outputs. */
	TBatchResult run();

   private:
	/** A pipeline for `overrides` (on top of the request's), with the debug
	 * outputs the request asks for attached. */
	std::unique_ptr<slam::CMappingPipeline> makePipeline(const slam::TMappingConfig& config);
	/** The whole rawlog through a fresh pipeline; with [odometry_timing]
	 * second_pass, once more from the start with the odometry time offset
	 * the first pass fitted, if it fitted one (the turns before the fit
	 * was clear are read right too). */
	std::unique_ptr<slam::CMappingPipeline> processRawlog(slam::TMappingConfig& config, TBatchResult& result);
	/** INI overrides of a second pass from the start, with what the first
	 * found ([odometry_timing] offset, [odometry_scale_check] scales); none:
	 * the first pass stands. */
	std::vector<std::string> secondPassOverrides(const slam::CMappingPipeline& pipeline);
	void readRawlog(slam::CMappingPipeline& pipeline, TBatchResult& result);
	void evaluate(const slam::CMappingPipeline& pipeline, TBatchResult& result);
	/** Scan-pair misfit of the reference and the final trajectory
	 * (eval/scan_consistency.h), printed; nullopt (and why, printed) when
	 * the rawlog was not read to its end or has several lasers and no
	 * [process] laser_label. */
	std::optional<eval::TScanConsistency> scanConsistency(const slam::CMappingPipeline& pipeline,
														  const common::TTrajectory2D& reference,
														  const TBatchResult& result);
	void writeEffectiveConfig(const slam::CMappingPipeline& pipeline, const slam::TOutputOptions& outputOptions);
	void printSummary(const slam::CMappingPipeline& pipeline, const TBatchResult& result);
	void printMatchSummary(const slam::CMappingPipeline& pipeline);
	void addDebugFrameWriter(slam::CMappingPipeline& pipeline, int every);

	TBatchRequest m_request;
	std::ostream& m_out;
	std::ostream& m_err;
};

}  // namespace hslam::batch
