/* MRPT's own icp-slam (which has no -p option) builds our map when the
 * plug-in module is preloaded: the map factory creates it from the
 * tiledOccupancyGrid_count key, icp-slam inserts the real laser scans of
 * MRPT's sample rawlog into it and dumps it (saveMetricMapRepresentationToFile). */
#include <gtest/gtest.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace
{
/** icp-slam INI: the demo's classic ICP settings, headless, our map next to the points map. */
std::string icpSlamIni(const std::string& outDir, bool withTiledMap)
{
	std::string ini = R"([ICP]
maxIterations = 80
thresholdDist = 0.3
thresholdAng_DEG = 5
ALFA = 0.8
smallestThresholdDist = 0.05
onlyClosestCorrespondences = true
ICP_algorithm = icpClassic
corresponding_points_decimation = 5
[MappingApplication]
rawlog_file = )" + std::string(HSLAM_MRPT_DATASETS_DIR) +
					  R"(/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog
rawlog_offset = 0
logOutput_dir = )" + outDir + R"(
LOG_FREQUENCY = 1000
SAVE_3D_SCENE = 0
SAVE_POSE_LOG = 0
SHOW_PROGRESS_3D_REAL_TIME = 0
CAMERA_3DSCENE_FOLLOWS_ROBOT = 0
SHOW_PROGRESS_3D_REAL_TIME_DELAY_MS = 0
SHOW_LASER_SCANS_3D = false
localizationLinDistance = 0.2
localizationAngDistance = 5
insertionLinDistance = 0.5
insertionAngDistance = 20
minICPgoodnessToAccept = 0.40
matchAgainstTheGrid = 0
pointsMap_count = 1
)";
	if (withTiledMap)
		ini += "tiledOccupancyGrid_count = 1\n"
			   "[MappingApplication_tiledOccupancyGrid_00_insertOpts]\n"
			   "laser_max_range_m = 5.0\n";
	return ini;
}

std::vector<std::string> tiledMapImages(const std::string& dir)
{
	std::vector<std::string> out;
	for (const auto& e : std::filesystem::directory_iterator(dir))
		if (e.path().filename().string().find("CTiledOccupancyGridMap2D") != std::string::npos &&
			e.path().extension() == ".png")
			out.push_back(e.path().string());
	return out;
}
}  // namespace

TEST(TiledMap, IcpSlamBuildsOurMapThroughThePlugin)
{
	const std::string plugin = std::string(HSLAM_BINARY_DIR) + "/lib/libhslam-maps-plugin.so";
	ASSERT_TRUE(std::filesystem::exists(plugin)) << plugin;
	for (const bool preload : {true, false})
	{
		hslam::testing::CTempDir dir;
		const std::string ini = dir.file("icp.ini"), out = dir.file("out");
		std::ofstream(ini) << icpSlamIni(out, true);
		const std::string cmd = std::string(preload ? "LD_PRELOAD=" + plugin + " " : "") + "icp-slam " + ini +
								" < /dev/null > " + dir.file("log.txt") + " 2>&1";
		if (hslam::testing::runCommand(cmd) != 0)
		{
			std::ifstream log(dir.file("log.txt"));
			FAIL() << cmd << "\n" << std::string(std::istreambuf_iterator<char>(log), {});
		}
		const auto images = tiledMapImages(out);
		if (!preload)
		{
			EXPECT_TRUE(images.empty());  // without the plug-in MRPT ignores the key
			continue;
		}
		ASSERT_EQ(images.size(), 1u);
		EXPECT_GT(std::filesystem::file_size(images[0]), 1000u);
	}
}
