/* hslam: the two human/script-facing files of a run, written last by the
 * batch processor: summary.json (run_summary.h) and report.html
 * (html_report.h). */
#pragma once

#include <hslam/batch/CBatchProcessor.h>

#include <string>
#include <vector>

namespace hslam::batch
{
/** Writes summary.json and report.html into request.output_dir; returns the
 * two paths. `wall_s` is the run's duration so far. */
std::vector<std::string> writeRunReport(const slam::CMappingPipeline& pipeline, const TBatchRequest& request,
										const TBatchResult& result, double wall_s);
}  // namespace hslam::batch
