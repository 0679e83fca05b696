#include <gtest/gtest.h>
#include <hslam/batch/CBatchProcessor.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/img/CImage.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

TEST(DynamicBatchOutputs, TracksCsvAndDebugImages)
{
	hslam::testing::CTempDir dir;
	hslam::batch::TBatchRequest request;
	request.config_file = std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-legs-hokuyo-rules.ini";
	request.overrides = {"laser_model.max_range_m=5.5", "output.dynamic_debug_images=true",
						 "output.dynamic_debug_max_images=5", "output.write_tiles=false"};
	request.input_rawlog = std::string(HSLAM_SHARED_DATASETS_DIR) + "/legs/demo_stationary_simple_environment.rawlog";
	request.output_dir = dir.file("out");
	request.show_progress = false;
	std::ostringstream out, err;
	hslam::batch::CBatchProcessor(request, out, err).run();
	EXPECT_NE(out.str().find("tracks.csv"), std::string::npos);

	std::ifstream csv(dir.file("out/tracks.csv"));
	std::string header, line;
	ASSERT_TRUE(std::getline(csv, header));
	EXPECT_EQ(header.rfind("t_s,scan,kind,id,state,seen,x_robot_m,y_robot_m,x_world_m,y_world_m,vx_world_mps", 0), 0u);
	size_t rows = 0, dynamicPersons = 0;
	std::set<std::string> kinds;
	while (std::getline(csv, line))
	{
		++rows;
		std::stringstream ls(line);
		std::string t, scan, kind, id, state;
		std::getline(ls, t, ','), std::getline(ls, scan, ','), std::getline(ls, kind, ','), std::getline(ls, id, ',');
		std::getline(ls, state, ',');
		kinds.insert(kind);
		dynamicPersons += kind == "person" && state == "dynamic";
	}
	EXPECT_GT(rows, 1000u);
	EXPECT_EQ(kinds, (std::set<std::string>{"leg", "person"}));
	EXPECT_GT(dynamicPersons, 100u);

	size_t images = 0;
	for (const auto& e : std::filesystem::directory_iterator(dir.file("out/dynamic")))
	{
		mrpt::img::CImage img;
		ASSERT_TRUE(img.loadFromFile(e.path().string())) << e.path();
		EXPECT_EQ(img.getWidth(), 600u);
		++images;
	}
	EXPECT_EQ(images, 5u);
}
