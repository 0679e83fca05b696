/* hslam tests: hslam-umbmark on the simulated UMBmark sample
 * (rawlog_samples/umbmark: Ed = 1.001, Eb = 1.004), on its rawlog, on the
 * thesis's tables 1-2, its INI output, and bad input. */
#include <gtest/gtest.h>
#include <hslam/calib/COdometryCorrection.h>
#include <hslam/common/options_io.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>
#include <sstream>

#include <array>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>

namespace
{
struct TRun
{
	int exitCode = -1;
	std::string out;
};

TRun run(const std::string& args)
{
	const auto r = hslam::testing::runCapturingOutput(std::string(HSLAM_BIN_DIR) + "/hslam-umbmark " + args);
	return {r.exitCode, r.out};
}

double valueAfter(const std::string& text, const std::string& key)
{
	const auto pos = text.rfind("\n" + key);
	if (pos == std::string::npos) return 0;
	return std::stod(text.substr(pos + 1 + key.size()));
}
const std::string kSample = std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/umbmark";
}  // namespace

TEST(UmbmarkApp, SampleFolderRecoversTheSimulatedErrors)
{
	hslam::testing::CTempDir tmp;
	const auto r = run(kSample + " -o " + tmp.file("corr.ini"));
	ASSERT_EQ(r.exitCode, 0) << r.out;
	const double ed = valueAfter(r.out, "Ed="), eb = valueAfter(r.out, "Eb=");
	// The sample has 3 runs per direction with the simulator's default random
	// slip (wheel 0.001 m/sqrt(m), heading 0.002 rad/sqrt(rad)): the centres of
	// gravity carry ~5 cm of random error, ~0.2 deg on alpha and beta, so the
	// sample pins Ed - 1 and Eb - 1 to ~30 % (measured: -13 %, +20 %). The 15 %
	// check on Ed = 1.001, Eb = 1.004 is in umbmark_simulated_unittest.cpp.
	EXPECT_NEAR(ed - 1.0, 0.001, 0.3 * 0.001) << r.out;
	EXPECT_NEAR(eb - 1.0, 0.004, 0.3 * 0.004) << r.out;
	EXPECT_NE(r.out.find("3 runs"), std::string::npos) << "three CW and three CCW runs";
	// The INI section loads into the correction every odometry applies.
	mrpt::config::CConfigFile ini(tmp.file("corr.ini"));
	hslam::calib::TOdometryCorrection c;
	hslam::common::loadOptions(c, ini, "odometry_correction");
	EXPECT_TRUE(c.enabled);
	EXPECT_NEAR(c.wheelbase_ratio, eb, 1e-6);
	EXPECT_NEAR(c.left_factor, 2.0 / (ed + 1.0), 1e-6);
	// Never overwritten.
	EXPECT_EQ(run(kSample + " -o " + tmp.file("corr.ini")).exitCode, 1);
}

TEST(UmbmarkApp, RawlogWithGroundTruthAgreesWithTheWaypoints)
{
	const auto r = run("-i " + kSample + "/sim.rawlog");
	ASSERT_EQ(r.exitCode, 0) << r.out;
	// Same runs, cut from the 10 Hz odometry instead of the waypoint events.
	const auto w = run(kSample);
	EXPECT_NEAR(valueAfter(r.out, "Ed="), valueAfter(w.out, "Ed="), 0.00002) << r.out;
	EXPECT_NEAR(valueAfter(r.out, "Eb="), valueAfter(w.out, "Eb="), 0.0001) << r.out;
}

TEST(UmbmarkApp, ThesisTablesAndBadInput)
{
	const auto r = run("--endpoints " + std::string(HSLAM_SOURCE_DIR) + "/docs/calib/thesis-tables-1-2.csv --side-m 4.4");
	ASSERT_EQ(r.exitCode, 0) << r.out;
	EXPECT_NE(r.out.find("group 400mm_s"), std::string::npos);
	EXPECT_NE(r.out.find("all groups pooled"), std::string::npos);
	hslam::testing::CTempDir tmp;
	std::ofstream(tmp.file("bad.csv")) << "group,direction,x_cm,y_cm\n50,cw,-8.5,-5\n50,sideways,1,2\n";
	const auto bad = run("--endpoints " + tmp.file("bad.csv") + " --side-m 4.4");
	EXPECT_EQ(bad.exitCode, 1);
	EXPECT_NE(bad.out.find("bad.csv:3"), std::string::npos) << bad.out;
	EXPECT_EQ(run(tmp.file("missing-folder")).exitCode, 1);
}

namespace
{
/** Drive INI + simulator INI (sim-umbmark.ini with the given errors and a
 * small random slip) in `tmp`; returns the drive INI's path. */
std::string writeDriveInis(const hslam::testing::CTempDir& tmp, double ed, double eb, int runs)
{
	std::ifstream in(std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-umbmark.ini");
	std::stringstream ss;
	ss << in.rdbuf();
	mrpt::config::CConfigFileMemory sim(ss.str());
	sim.write("world", "scene_file", std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-worlds/umbmark.scene");
	sim.write("robot", "ed_wheel_diameter_ratio", std::to_string(ed));
	sim.write("robot", "eb_wheelbase_ratio", std::to_string(eb));
	// As UmbmarkSimulated.RecoversEdEbAndCorrectionReducesEmaxTenfold: a
	// small random slip, so that 5 runs per direction pin Ed, Eb to 15 %.
	sim.write("robot", "wheel_noise_m_per_sqrt_m", "0.0001");
	sim.write("laser", "enabled", "false");
	std::ofstream(tmp.file("sim.ini")) << sim.getContent();
	std::ofstream(tmp.file("drive.ini")) << "[umbmark_drive]\nsim_ini = sim.ini\nside_m = 4.4\nruns_per_direction = "
										 << runs << "\n";
	return tmp.file("drive.ini");
}
}  // namespace

// Thesis 4.1: the tool drives the 4.4 m square 5 times each way itself, records
// it and recovers the simulated robot's Ed, Eb from that recording.
TEST(UmbmarkApp, DriveRecoversKnownErrorsFromItsOwnRecording)
{
	hslam::testing::CTempDir tmp;
	const double ed = 1.001, eb = 1.004;
	const auto r = run("--drive " + writeDriveInis(tmp, ed, eb, 5) + " --drive-out " + tmp.file("rec") + " -o " +
					   tmp.file("corr.ini"));
	ASSERT_EQ(r.exitCode, 0) << r.out;
	EXPECT_TRUE(std::filesystem::exists(tmp.file("rec/umbmark.rawlog")));
	EXPECT_TRUE(std::filesystem::exists(tmp.file("rec/ground_truth.tum")));
	EXPECT_NE(r.out.find("5 runs"), std::string::npos) << "five CW and five CCW runs\n" << r.out;
	const double edFound = valueAfter(r.out, "Ed="), ebFound = valueAfter(r.out, "Eb=");
	std::printf("--drive: Ed %.5f (true %.4f), Eb %.5f (true %.4f)\n", edFound, ed, ebFound, eb);
	EXPECT_NEAR(edFound - 1.0, ed - 1.0, 0.15 * (ed - 1.0)) << r.out;
	EXPECT_NEAR(ebFound - 1.0, eb - 1.0, 0.15 * (eb - 1.0)) << r.out;
	EXPECT_TRUE(std::filesystem::exists(tmp.file("corr.ini")));
	// The recording evaluates to the same numbers through -i.
	const auto again = run("-i " + tmp.file("rec/umbmark.rawlog"));
	ASSERT_EQ(again.exitCode, 0) << again.out;
	EXPECT_DOUBLE_EQ(valueAfter(again.out, "Ed="), edFound);
	EXPECT_DOUBLE_EQ(valueAfter(again.out, "Eb="), ebFound);
}

TEST(UmbmarkApp, DriveBadInputNamesTheFileAndKey)
{
	hslam::testing::CTempDir tmp;
	std::ofstream(tmp.file("bad.ini")) << "[umbmark_drive]\nside_m = -3\n";
	const auto bad = run("--drive " + tmp.file("bad.ini") + " --drive-out " + tmp.file("rec"));
	EXPECT_EQ(bad.exitCode, 1);
	EXPECT_NE(bad.out.find("bad.ini"), std::string::npos) << bad.out;
	EXPECT_NE(bad.out.find("side_m"), std::string::npos) << bad.out;
	std::ofstream(tmp.file("missing.ini")) << "[umbmark_drive]\nsim_ini = nowhere.ini\n";
	const auto missing = run("--drive " + tmp.file("missing.ini") + " --drive-out " + tmp.file("rec2"));
	EXPECT_EQ(missing.exitCode, 1);
	EXPECT_NE(missing.out.find("nowhere.ini"), std::string::npos) << missing.out;
	EXPECT_EQ(run("--drive " + tmp.file("bad.ini") + " -i x.rawlog").exitCode, 1) << "one input only";
}
