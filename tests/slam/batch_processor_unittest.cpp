#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/batch/CBatchProcessor.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CFileOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hslam;

namespace
{
const std::string kSample =
	std::string(HSLAM_MRPT_DATASETS_DIR) + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
using hslam::slam::testing::kDefaultIni;

using hslam::slam::testing::runBatch;

/** Decompressed bytes of a (gz) rawlog. */
std::string rawlogBytes(const std::string& path)
{
	mrpt::io::CFileGZInputStream in(path);
	std::string bytes;
	char buffer[65536];
	for (size_t n; (n = in.Read(buffer, sizeof(buffer))) > 0;) bytes.append(buffer, n);
	return bytes;
}

void writeBytes(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}
}  // namespace

TEST(BatchProcessor, MrptSampleRawlogEndToEnd)
{
	ASSERT_TRUE(std::filesystem::exists(kSample)) << kSample;
	hslam::testing::CTempDir dir;
	const auto result = runBatch(kSample, dir.path().string(), {"pose_estimation.method=odometry"});
	EXPECT_TRUE(result.input_error.empty()) << result.input_error;
	EXPECT_EQ(result.counters.laser_scans, 225u);
	EXPECT_EQ(result.counters.odometry_readings, 224u);
	for (const char* f : {"map.png", "map.gridmap.gz", "trajectory.tum", "odometry.tum", "timing.csv",
						  "config_used.ini", "tiles/tile_0_0.png"})
		EXPECT_TRUE(std::filesystem::exists(dir.path() / f)) << f;

	// The online trajectory is the composition of the rawlog's odometry
	// actions (trajectory.tum is the loop-closure back-end's correction of it).
	mrpt::poses::CPose2D expected;
	io::CRawlogReader reader(kSample);
	io::TRawlogEntry entry;
	while (reader.next(entry))
		if (entry.actions)
			if (auto move = entry.actions->getActionByClass<mrpt::obs::CActionRobotMovement2D>())
				expected = expected + move->poseChange->getMeanVal();
	const auto trajectory = common::readTumFile(dir.file("trajectory_online.tum"));
	ASSERT_EQ(trajectory.size(), 225u);
	ASSERT_EQ(common::readTumFile(dir.file("trajectory.tum")).size(), 225u);
	EXPECT_NEAR(trajectory.back().pose.x, expected.x(), 1e-5);
	EXPECT_NEAR(trajectory.back().pose.y, expected.y(), 1e-5);

	// map.gridmap.gz loads as an MRPT grid with free and occupied cells.
	mrpt::maps::COccupancyGridMap2D loaded;
	mrpt::io::CFileGZInputStream in(dir.file("map.gridmap.gz"));
	mrpt::serialization::archiveFrom(in) >> loaded;
	size_t occupied = 0, free = 0;
	for (unsigned y = 0; y < loaded.getSizeY(); ++y)
		for (unsigned x = 0; x < loaded.getSizeX(); ++x)
		{
			const auto c = benchdata::classifyOccupancy(1.0 - loaded.getCell(x, y), 0.01);
			occupied += c == benchdata::ECellClass::occupied;
			free += c == benchdata::ECellClass::free;
		}
	EXPECT_GT(occupied, 200u);
	EXPECT_GT(free, 5 * occupied);
}

TEST(BatchProcessor, TruncatedRawlogKeepsWhatWasProcessed)
{
	hslam::testing::CTempDir dir;
	const std::string bytes = rawlogBytes(kSample);
	ASSERT_GT(bytes.size(), 100000u);
	writeBytes(dir.file("truncated.rawlog"), bytes.substr(0, bytes.size() / 2));
	const auto result = runBatch(dir.file("truncated.rawlog"), dir.file("out"));
	EXPECT_NE(result.input_error.find("truncated.rawlog: entry"), std::string::npos) << result.input_error;
	EXPECT_NE(result.input_error.find("truncated"), std::string::npos) << result.input_error;
	EXPECT_GT(result.counters.laser_scans, 50u);
	EXPECT_LT(result.counters.laser_scans, 225u);
	const auto trajectory = common::readTumFile(dir.file("out/trajectory.tum"));
	EXPECT_EQ(trajectory.size(), result.counters.laser_scans);
	EXPECT_TRUE(std::filesystem::exists(dir.file("out/map.png")));
}

TEST(BatchProcessor, CorruptRawlogIsReportedNotCrashed)
{
	hslam::testing::CTempDir dir;
	std::string bytes = rawlogBytes(kSample);
	for (size_t i = bytes.size() / 3; i < bytes.size() / 3 + 64; ++i) bytes[i] = static_cast<char>(0xA5);
	writeBytes(dir.file("corrupt.rawlog"), bytes);
	const auto result = runBatch(dir.file("corrupt.rawlog"), dir.file("out"));
	EXPECT_NE(result.input_error.find("corrupt.rawlog: entry"), std::string::npos) << result.input_error;
	EXPECT_GT(result.counters.laser_scans, 30u);
	EXPECT_TRUE(std::filesystem::exists(dir.file("out/trajectory.tum")));
}

TEST(BatchProcessor, MissingInputAndBadConfigAreClearErrors)
{
	hslam::testing::CTempDir dir;
	try
	{
		runBatch(dir.file("nope.rawlog"), dir.file("out"));
		FAIL();
	}
	catch (const io::rawlog_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("nope.rawlog"), std::string::npos);
	}
	EXPECT_THROW(runBatch(kSample, dir.file("out"), {"grid.resolution_m=-1"}), common::config_error);
	EXPECT_THROW(runBatch(kSample, dir.file("out"), {"grid.resoluton_m=0.1"}), common::config_error);
	EXPECT_THROW(runBatch(kSample, dir.file("out"), {"gird.resolution_m=0.1"}), common::config_error);
	EXPECT_THROW(runBatch(kSample, dir.file("out"), {"pose_estimation.method=magic"}), common::config_error);
}

TEST(BatchProcessor, SetOverridesChangeTheRun)
{
	hslam::testing::CTempDir dir;
	const auto result = runBatch(kSample, dir.path().string(), {"laser_model.max_range_m=8", "grid.tile_size_cells=50"});
	EXPECT_TRUE(result.input_error.empty());
	std::ifstream used(dir.file("config_used.ini"));
	std::stringstream text;
	text << used.rdbuf();
	EXPECT_NE(text.str().find("max_range_m = 8"), std::string::npos) << text.str();
	EXPECT_NE(text.str().find("tile_size_cells = 50"), std::string::npos);
	size_t tiles = 0;
	for (const auto& f : std::filesystem::directory_iterator(dir.path() / "tiles")) tiles += f.is_regular_file();
	EXPECT_GT(tiles, 8u);  // 5 m tiles: the 30 m loop spans many of them
}

TEST(BatchProcessor, AppCommandLine)
{
	hslam::testing::CTempDir dir;
	const std::string app = std::string(HSLAM_BIN_DIR) + "/hslam-process";
	EXPECT_EQ(hslam::testing::runCommand(app + " --help > /dev/null"), 0);
	EXPECT_NE(hslam::testing::runCommand(app + " -c " + kDefaultIni + " -i /nonexistent.rawlog -o " + dir.file("o") +
								  " 2> " + dir.file("err.txt")),
			  0);
	std::ifstream err(dir.file("err.txt"));
	std::string message((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
	EXPECT_NE(message.find("/nonexistent.rawlog"), std::string::npos) << message;
}

TEST(BatchProcessor, OdometryGapCommentMeansUnknownMotion)
{
	// Observations-only rawlog as written by hslam-carmen2rawlog: the third
	// scan has no odometry but an ODOMETRY_GAP comment instead.
	hslam::testing::CTempDir dir;
	{
		mrpt::io::CFileGZOutputStream out(dir.file("gap.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(out);
		double t = 1000.0;
		const auto odometry = [&](double x) {
			mrpt::obs::CObservationOdometry o;
			o.odometry = mrpt::poses::CPose2D(x, 0, 0);
			o.timestamp = mrpt::Clock::fromDouble(t);
			arch << o;
		};
		const auto scan = [&]() {
			mrpt::obs::CObservation2DRangeScan s;
			s.aperture = static_cast<float>(M_PI);
			s.resizeScan(5);
			for (size_t i = 0; i < 5; ++i) s.setScanRange(i, 1.0f), s.setScanRangeValidity(i, true);
			s.timestamp = mrpt::Clock::fromDouble(t);
			t += 1.0;
			arch << s;
		};
		odometry(0.0), scan();
		odometry(1.0), scan();
		mrpt::obs::CObservationComment gap;
		gap.text = "ODOMETRY_GAP: odometry missing between front scans 1 and 2";
		arch << gap;
		scan();
		odometry(2.0), scan();  // the importer's chain: +1 m after the gap
	}
	const auto result = runBatch(dir.file("gap.rawlog"), dir.file("out"), {"pose_estimation.method=odometry"});
	EXPECT_EQ(result.counters.odometry_gaps, 1u);
	const auto trajectory = common::readTumFile(dir.file("out/trajectory.tum"));
	ASSERT_EQ(trajectory.size(), 4u);
	EXPECT_NEAR(trajectory[1].pose.x, 1.0, 1e-9);
	EXPECT_NEAR(trajectory[2].pose.x, 1.0, 1e-9);  // unknown motion: pose kept, not invented
	EXPECT_NEAR(trajectory[3].pose.x, 2.0, 1e-9);
}

TEST(BatchProcessor, AFailedOutputIsNamedAndLeavesNoPartialFile)
{
	// pose_plot.png cannot be renamed into place (a non-empty folder holds its
	// name): the run must fail naming it, keep the outputs written before it
	// complete, and leave no temporary file behind.
	hslam::testing::CTempDir dir;
	std::filesystem::create_directories(dir.file("out/pose_plot.png"));
	std::ofstream(dir.file("out/pose_plot.png/keep.txt")) << "not ours";
	batch::TBatchRequest request;
	request.config_file = kDefaultIni;
	request.input_rawlog = kSample;
	request.output_dir = dir.file("out");
	request.overwrite = true;
	request.show_progress = false;
	std::ostringstream out, err;
	std::string message;
	try
	{
		batch::CBatchProcessor(request, out, err).run();
	}
	catch (const std::exception& e)
	{
		message = e.what();
	}
	EXPECT_NE(message.find("pose_plot.png: write failed or cut short"), std::string::npos) << message;
	const auto trajectory = common::readTumFile(dir.file("out/trajectory.tum"));  // written before the plot
	EXPECT_GT(trajectory.size(), 200u);
	for (const auto& f : std::filesystem::recursive_directory_iterator(dir.file("out")))
		EXPECT_EQ(f.path().filename().string().rfind(".hslam-tmp-", 0), std::string::npos) << f.path();
	EXPECT_TRUE(std::filesystem::exists(dir.file("out/pose_plot.png/keep.txt")));
}
