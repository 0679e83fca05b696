/* hslam tests: the CARMEN importer on a real log (intel-corrected) and the
 * result accepted by MRPT's own rawlog-edit; plus the app's exit codes. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <filesystem>

#include "carmen_test_utils.h"

using namespace hslam::io;
using namespace hslam::testing::carmen;

namespace
{
std::string intelLog() { return std::string(HSLAM_SHARED_DATASETS_DIR) + "/carmen/intel-corrected.log.gz"; }
std::string appPath() { return std::string(HSLAM_BIN_DIR) + "/hslam-carmen2rawlog"; }
}  // namespace

TEST(CarmenImportRealData, IntelCorrected)
{
	ASSERT_TRUE(std::filesystem::exists(intelLog())) << "missing dataset " << intelLog();
	hslam::testing::CTempDir dir;
	const std::string rawlog = dir.file("intel.rawlog"), tum = dir.file("intel.tum");
	const auto report = convertCarmenLog(intelLog(), rawlog, tum, {});
	EXPECT_EQ(report.frontScans, 910u);
	EXPECT_EQ(report.referencePoses, 910u);
	EXPECT_EQ(report.odometryObservations, 1u + 909u - report.odometryGaps);
	EXPECT_EQ(report.odometryGaps, 0u);  // every intel scan has raw odometry after its anchor
	EXPECT_EQ(report.odometryAnchors, 910u);
	EXPECT_EQ(report.malformedLinesSkipped, 0u);
	ASSERT_TRUE(report.noReturn_m.has_value());
	EXPECT_NEAR(*report.noReturn_m, 81.83, 1e-9);
	// intel's ipc timestamps go backwards 4 times (at most 0.86 s): repaired, so
	// the true clock is kept (first scan at 32.9068 s, last at 2683.77 s).
	EXPECT_EQ(report.clockUsed, "ipc");
	const auto reference = hslam::common::readTumFile(tum);
	ASSERT_EQ(reference.size(), 910u);
	EXPECT_NEAR(reference.front().t_s, 32.9068, 1e-6);
	EXPECT_NEAR(reference.back().t_s, 2683.77, 1e-6);

	const auto observations = readRawlog(rawlog);
	EXPECT_EQ(ofType<mrpt::obs::CObservation2DRangeScan>(observations).size(), 910u);
	EXPECT_EQ(ofType<mrpt::obs::CObservationOdometry>(observations).size(), report.odometryObservations);

	const std::string info = dir.file("info.txt");
	ASSERT_EQ(hslam::testing::runCommand("rawlog-edit --info -i '" + rawlog + "' > '" + info + "' 2>&1"), 0)
		<< readText(info);
	const std::string text = readText(info);
	EXPECT_NE(text.find("Observations format               : Yes"), std::string::npos) << text;
	EXPECT_NE(text.find("LASER /    910"), std::string::npos) << text;
	EXPECT_NE(text.find("ODOMETRY /    910"), std::string::npos) << text;
}

TEST(CarmenImportApp, ExitCodesAndOneLineErrors)
{
	ASSERT_TRUE(std::filesystem::exists(appPath())) << "build the hslam-carmen2rawlog target first: " << appPath();
	hslam::testing::CTempDir dir;
	writeText(dir.file("ok.log"), flaser(181, {0, 0, 0}, 1.0) + anchor({0, 0, 0}) + odom({0.2, 0, 0}, 1.5) +
									  flaser(181, {0.2, 0, 0}, 2.0));
	const std::string out = dir.file("out.txt");
	EXPECT_EQ(hslam::testing::runCommand("'" + appPath() + "' '" + dir.file("ok.log") + "' '" + dir.file("ok.rawlog") +
										 "' --reference '" + dir.file("ok.tum") + "' > '" + out + "' 2>&1"),
			  0)
		<< readText(out);
	EXPECT_NE(readText(out).find("scans written: 2 front"), std::string::npos) << readText(out);

	writeText(dir.file("bad.log"), "FLASER 181 1 2\n");
	EXPECT_EQ(hslam::testing::runCommand("'" + appPath() + "' '" + dir.file("bad.log") + "' '" +
										 dir.file("bad.rawlog") + "' --reference '" + dir.file("bad.tum") + "' > '" +
										 out + "' 2>&1"),
			  1);
	const std::string error = readText(out);
	EXPECT_NE(error.find("bad.log:1:"), std::string::npos) << error;
	EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << error;

	EXPECT_EQ(hslam::testing::runCommand("'" + appPath() + "' '" + dir.file("ok.log") + "' '" +
										 dir.file("ok2.rawlog") + "' --reference '" + dir.file("ok2.tum") +
										 "' --clock gps > '" + out + "' 2>&1"),
			  1);
	EXPECT_NE(readText(out).find("clock"), std::string::npos) << readText(out);
}
