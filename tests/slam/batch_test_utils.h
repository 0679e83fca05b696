// Shared by the tests/slam programs: run the batch job (libs/batch) as hslam-process does.
#pragma once

#include <hslam/batch/CBatchProcessor.h>
#include <hslam/common/config_overrides.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/io/carmen_import.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace hslam::slam::testing
{
inline const std::string kDefaultIni = std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini";

/** The batch job on `input` with the default INI plus `overrides`
 * ("SECTION.KEY=VALUE"), output into `outdir`, console output discarded. */
inline batch::TBatchResult runBatch(const std::string& input, const std::string& outdir,
							 const std::vector<std::string>& overrides = {})
{
	batch::TBatchRequest request;
	request.config_file = kDefaultIni;
	request.overrides = overrides;
	request.input_rawlog = input;
	request.output_dir = outdir;
	request.show_progress = false;
	std::ostringstream out, err;
	return batch::CBatchProcessor(request, out, err).run();
}
/** ../shared/datasets/carmen/NAME-corrected.log.gz converted by our CARMEN
 * importer into DIR/NAME.rawlog and DIR/NAME.tum (the corrected poses). */
inline void convertCarmenReferenceLog(const std::string& name, const std::string& dir)
{
	io::convertCarmenLog(std::string(HSLAM_SHARED_DATASETS_DIR) + "/carmen/" + name + "-corrected.log.gz",
						 dir + "/" + name + ".rawlog", dir + "/" + name + ".tum", io::TCarmenImportOptions());
}

/** The pipeline (default INI plus `overrides`) over `rawlog` whose odometry
 * readings pass through `rewrite` first (the reading, and the scans read so
 * far): a robot whose wheels froze, slipped or were never read. With
 * `skippedScans`, the log starts after that many scans. Finished. */
inline std::unique_ptr<CMappingPipeline> runWithRewrittenOdometry(
	const std::string& rawlog, const std::vector<std::string>& overrides,
	const std::function<void(mrpt::poses::CPose2D& odometry, size_t scans)>& rewrite, size_t skippedScans = 0)
{
	auto pipeline = std::make_unique<CMappingPipeline>(common::loadConfigWithOverrides(kDefaultIni, overrides));
	io::CRawlogReader reader(rawlog);
	size_t scans = 0;
	for (io::TRawlogEntry e; reader.next(e);)
	{
		if (e.observation && IS_CLASS(*e.observation, mrpt::obs::CObservation2DRangeScan)) ++scans;
		if (scans <= skippedScans && skippedScans > 0) continue;  // the log started later
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.observation))
			rewrite(odo->odometry, scans);
		pipeline->processEntry(e);
	}
	pipeline->finish();
	return pipeline;
}
}  // namespace hslam::slam::testing
