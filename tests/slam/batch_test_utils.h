// Shared by the tests/slam programs: run the batch job (libs/batch) as hslam-process does.
#pragma once

#include <hslam/batch/CBatchProcessor.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/test_paths.h>

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
}  // namespace hslam::slam::testing
