#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/common/config_overrides.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <iostream>
#include <sstream>

namespace
{
struct TResult
{
	size_t occupied = 0, trackRows = 0, dynamicRows = 0;
};

/** Maps the real static-scanner log with people walking, filter on or off. */
TResult mapDemo(bool exclude, size_t maxScans)
{
	// The Hokuyo rules (0.35 deg) with the switch, and the laser's 5.6 m range.
	const auto cfg = hslam::common::loadConfigWithOverrides(
		std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-legs-hokuyo-rules.ini",
		{std::string("dynamic_objects.enabled=") + (exclude ? "true" : "false"), "laser_model.max_range_m=5.5"});
	hslam::slam::CMappingPipeline pipeline(cfg);
	hslam::io::CRawlogReader reader(std::string(HSLAM_SHARED_DATASETS_DIR) +
									"/legs/demo_stationary_simple_environment.rawlog");
	hslam::io::TRawlogEntry entry;
	while (pipeline.counters().laser_scans < maxScans && reader.next(entry)) pipeline.processEntry(entry);
	TResult r;
	r.occupied = hslam::benchdata::occupiedCells(pipeline.grid()).size();
	r.trackRows = pipeline.trackRows().size();
	for (const auto& row : pipeline.trackRows()) r.dynamicRows += row.track.state == hslam::dynamic::ETrackState::dynamic;
	EXPECT_EQ(pipeline.dynamicFilter() != nullptr, exclude);
	return r;
}
}  // namespace

TEST(PipelineExclusion, FewerOccupiedCellsWithPeopleExcluded)
{
	const auto without = mapDemo(false, 1265), with = mapDemo(true, 1265);
	EXPECT_EQ(without.trackRows, 0u);
	EXPECT_GT(with.dynamicRows, 100u);
	// Measured: 417 -> 196 occupied cells.
	std::cout << "occupied cells without / with exclusion: " << without.occupied << " / " << with.occupied << "\n";
	EXPECT_LT(static_cast<double>(with.occupied), 0.75 * static_cast<double>(without.occupied))
		<< "without " << without.occupied << ", with " << with.occupied;
}

TEST(PipelineExclusion, BadDynamicOptionsNameTheSection)
{
	mrpt::config::CConfigFileMemory cfg(std::string("[dynamic_objects]\nfind_interv_bands_m = 2 1\n"));
	try
	{
		hslam::slam::CMappingPipeline pipeline(cfg);
		FAIL() << "no error";
	}
	catch (const hslam::common::config_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("[dynamic_objects] find_interv_bands_m"), std::string::npos) << e.what();
	}
}
