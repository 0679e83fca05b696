/* hslam: report.html, the page a person opens after an hslam-process run.
 * Plain static HTML beside the run's files: it references the PNGs by
 * relative paths (no network fetch, no script) and shows the summary figures
 * (summary.json), the warnings, the map and sensor maps, the pose plot, the
 * timing table, the evaluation figures, the leg and person tracks, the TBF
 * sonar corners and the effective configuration (config_used.ini).
 * Elements carrying a summary.json figure have id="fig-<key>" (tests and
 * scripts read them). */
#pragma once

#include <hslam/slam/CMappingPipeline.h>
#include <hslam/batch/run_summary.h>

#include <string>

namespace hslam::batch
{
/** Writes `dir`/report.html; only images that exist in `dir` are referenced.
 * Throws std::runtime_error naming the file on a write failure. */
void writeHtmlReport(const TRunSummary& summary, const slam::CMappingPipeline& pipeline, const std::string& dir);

/** Text with &, <, >, " escaped for HTML. */
std::string htmlEscape(const std::string& text);

}  // namespace hslam::batch
