#include <hslam/batch/html_report.h>
#include <hslam/batch/run_report.h>
#include <hslam/batch/run_summary.h>

namespace hslam::batch
{
std::vector<std::string> writeRunReport(const slam::CMappingPipeline& pipeline, const TBatchRequest& request,
										const TBatchResult& result, double wall_s)
{
	const auto summary = summarizeRun(pipeline, request, result, wall_s);
	const std::string json = request.output_dir + "/summary.json";
	writeRunSummaryJson(summary, json);
	writeHtmlReport(summary, pipeline, request.output_dir);
	return {json, request.output_dir + "/report.html"};
}
}  // namespace hslam::batch
