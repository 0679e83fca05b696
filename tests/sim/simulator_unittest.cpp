/* Tests of the simulation loop and the hslam-simulate app: velocity scripts,
 * sensor rates, determinism from the seed (byte-identical rawlogs), config
 * errors, and the end-to-end chain simulate -> hslam-process -> hslam-evaluate. */
#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/sim/CSimulator.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace hslam::sim;

namespace
{
struct TCountingSink : ISimulationSink
{
	size_t odo = 0, scans = 0, sonars = 0;
	std::vector<TSimulationFrame> scanFrames;
	void onOdometry(const mrpt::obs::CObservationOdometry&, const TSimulationFrame&) override { ++odo; }
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan&, const std::vector<TObjectTag>&,
					 const TSimulationFrame& f) override
	{
		++scans;
		scanFrames.push_back(f);
	}
	void onSonar(const mrpt::obs::CObservationRange&, const std::vector<TSonarEcho>&, const TSimulationFrame&) override
	{
		++sonars;
	}
};

std::string readFile(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

std::string sampleIni(const std::string& name) { return std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-" + name + ".ini"; }

int simulate(const std::string& ini, const std::string& out, const std::string& extra)
{
	return hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-simulate -q -c " + ini + " -o " + out + " " +
									  extra + " >" + out + ".log 2>&1");
}
}  // namespace

TEST(SimSimulator, VelocityScriptGivesStraightTruthAndSensorRates)
{
	TSimulatorConfig cfg;
	cfg.path.mode = "velocity";
	cfg.path.commands = "10 0.5 0";
	cfg.simulation.settle_s = 0;
	cfg.laser.rate_hz = 5;
	TScene scene = parseSceneText("room -1 -3 12 -3 12 3 -1 3\n", "box");
	CSimulator sim(cfg, std::move(scene));
	TCountingSink sink;
	sim.run(sink);
	EXPECT_NEAR(sim.elapsed_s(), 10.0, 0.011);
	EXPECT_EQ(sink.odo, 101u);  // 10 Hz at t = 0, 0.1, ..., 10 s
	EXPECT_EQ(sink.scans, 51u);  // 5 Hz
	EXPECT_EQ(sink.sonars, 101u);
	for (const auto& f : sink.scanFrames) EXPECT_NEAR(f.true_pose.y, 0.0, 1e-12);
	// 0.5 m/s with the 1 m/s^2 acceleration limit: 5 m minus 0.125 m lost while accelerating.
	EXPECT_NEAR(sim.robot().truePose().x, 5.0 - 0.125, 0.01);
	EXPECT_NEAR(sink.scanFrames[10].t_s - sink.scanFrames[9].t_s, 0.2, 1e-6);  // UNIX-time doubles
}

TEST(SimSimulator, SensorSettingsDoNotChangeTheTruePath)
{
	auto finalPose = [](double laserNoise, bool sonar) {
		TSimulatorConfig cfg;
		cfg.path.mode = "velocity";
		cfg.path.commands = "5 0.4 10; 5 0.4 -10";
		cfg.robot.kinematics.wheel_noise_m_per_sqrt_m = 0.01;
		cfg.laser.noise_std_m = laserNoise;
		cfg.sonar.enabled = sonar;
		CSimulator sim(cfg, parseSceneText("room -5 -5 5 -5 5 5 -5 5\n", "box"));
		ISimulationSink ignore;
		sim.run(ignore);
		return sim.robot().truePose();
	};
	const auto a = finalPose(0.01, true), b = finalPose(0.05, false);
	EXPECT_EQ(a.x, b.x);
	EXPECT_EQ(a.phi, b.phi);
}

TEST(SimSimulator, ExternalCommandsDriveTheRobot)
{
	TSimulatorConfig cfg;
	cfg.path.mode = "external";
	cfg.robot.kinematics.max_rot_accel_rad_s2 = 0;
	CSimulator sim(cfg, parseSceneText("room -5 -5 5 -5 5 5 -5 5\n", "box"));
	TCountingSink sink;
	sim.setExternalCommand(TVelocityCommand{0.0, M_PI / 10});  // 18 deg/s
	for (int k = 0; k < 500; ++k) sim.step(sink);  // 5 s
	EXPECT_FALSE(sim.done());
	EXPECT_NEAR(sim.robot().truePose().phi, M_PI / 2, 1e-9);
	EXPECT_EQ(sink.scans, 50u);
}

TEST(SimSimulator, ConfigErrorsNameSectionAndKey)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("laser", "preset", "lms291");
	try
	{
		loadSimulatorConfig(cfg);
		FAIL();
	}
	catch (const hslam::common::config_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("[laser] preset"), std::string::npos) << e.what();
	}
	mrpt::config::CConfigFileMemory cfg2;
	cfg2.write("sonar", "cone_width", "30");
	EXPECT_THROW(loadSimulatorConfig(cfg2), hslam::common::config_error);
	TSimulatorConfig c;
	c.path.mode = "waypoints";
	c.path.waypoints = "";
	EXPECT_THROW(CSimulator(c, parseSceneText("wall 0 0 1 0\n", "x")), hslam::common::config_error);
}

TEST(SimApp, SameSeedGivesByteIdenticalRawlogOtherSeedDoesNot)
{
	hslam::testing::CTempDir dir;
	const std::string shortRun = "--set simulation.duration_s=15";
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("a"), shortRun), 0) << readFile(dir.file("a.log"));
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("b"), shortRun), 0);
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("c"), shortRun + " --set simulation.seed=7"), 0);
	const std::string a = readFile(dir.file("a/sim.rawlog")), b = readFile(dir.file("b/sim.rawlog")),
					  c = readFile(dir.file("c/sim.rawlog"));
	EXPECT_GT(a.size(), 10000u);
	EXPECT_EQ(a, b);
	EXPECT_NE(a, c);
	for (const char* f : {"ground_truth.tum", "people.csv", "beam_labels.csv", "sonar_truth.csv", "overview.png"})
		EXPECT_EQ(readFile(dir.file(std::string("a/") + f)), readFile(dir.file(std::string("b/") + f))) << f;
}

TEST(SimApp, OutputsAreReadableByMrptAndOurReaders)
{
	hslam::testing::CTempDir dir;
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("o"), "--set simulation.duration_s=20"), 0);
	// Rawlog: MRPT's rawlog-edit and our reader.
	ASSERT_EQ(hslam::testing::runCommand("rawlog-edit --info -i " + dir.file("o/sim.rawlog") + " >" +
										 dir.file("info.txt") + " 2>&1"),
			  0);
	const std::string info = readFile(dir.file("info.txt"));
	EXPECT_NE(info.find("Observations format               : Yes"), std::string::npos) << info;
	EXPECT_NE(info.find("LASER /    200"), std::string::npos) << info;
	EXPECT_NE(info.find("SONAR /    200"), std::string::npos) << info;
	EXPECT_NE(info.find("ODOMETRY /    200"), std::string::npos) << info;
	// Ground truth: one TUM pose per scan, people rows per scan and person.
	const auto truth = hslam::common::readTumFile(dir.file("o/ground_truth.tum"));
	ASSERT_EQ(truth.size(), 200u);
	EXPECT_NEAR(truth.front().pose.x, 1.5, 1e-9);
	std::ifstream people(dir.file("o/people.csv"));
	size_t rows = 0;
	for (std::string line; std::getline(people, line);) ++rows;
	EXPECT_EQ(rows, 1u + 2u * 200u);
	// Ground-truth map is an MRPT grid.
	mrpt::io::CFileGZInputStream in(dir.file("o/gt_map.gridmap.gz"));
	mrpt::maps::COccupancyGridMap2D grid;
	auto arch = mrpt::serialization::archiveFrom(in);
	arch >> grid;
	EXPECT_NEAR(grid.getResolution(), 0.05, 1e-6);
	EXPECT_LT(std::min(grid.getPos(-0.02, 4.0), grid.getPos(0.02, 4.0)), 0.5f);  // west wall occupied
	EXPECT_GT(grid.getPos(5.0, 4.0), 0.5f);  // middle free
	// Corners: the lab room has 4 concave room corners among them.
	EXPECT_NE(readFile(dir.file("o/corners.csv")).find("0,0.0000,0.0000,concave,90.0"), std::string::npos);
}

TEST(SimApp, UmbmarkLapEndsAtTheOdometryStartButNotInTruth)
{
	hslam::testing::CTempDir dir;
	ASSERT_EQ(simulate(sampleIni("umbmark"), dir.file("u"), "--set 'path.waypoints=4 0; 4 -4; 0 -4; 0 0'"), 0)
		<< readFile(dir.file("u.log"));
	std::ifstream f(dir.file("u/waypoints.csv"));
	std::vector<std::vector<double>> rows;
	std::string line;
	std::getline(f, line);  // header
	while (std::getline(f, line))
	{
		std::vector<double> v;
		std::stringstream ss(line);
		for (std::string cell; std::getline(ss, cell, ',');) v.push_back(std::stod(cell));
		rows.push_back(v);
	}
	ASSERT_EQ(rows.size(), 4u);
	const auto& end = rows.back();  // waypoint,t,true x,y,yaw,odometry x,y,yaw
	EXPECT_LT(std::hypot(end[5], end[6]), 0.03);  // odometry believes it is back
	const double trueError = std::hypot(end[2], end[3]);
	// Ed = 1.001, Eb = 1.004 over a 16 m clockwise lap: the errors add up to decimetres.
	EXPECT_GT(trueError, 0.1);
	EXPECT_LT(trueError, 1.0);
}

TEST(SimApp, GridmapWorldGivesTheSameWallsAsTheScene)
{
	// Simulate in a scene of walls, then again in its own ground-truth
	// .gridmap: the laser ranges agree within a cell.
	hslam::testing::CTempDir dir;
	std::ofstream(dir.file("walls.scene")) << "room 0 0 10 0 10 8 0 8\nbox 6 4 1 2 20\nwall 3 6 5 7\n";
	const std::string noNoise = "--set simulation.duration_s=0.05 --set laser.noise_std_m=0 ";
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("scene"), noNoise + "--set world.scene_file=" + dir.file("walls.scene")),
			  0)
		<< readFile(dir.file("scene.log"));
	ASSERT_EQ(simulate(sampleIni("lab"), dir.file("grid"),
					   noNoise + "--set world.scene_file= --set world.gridmap_file=" + dir.file("scene/gt_map.gridmap.gz")),
			  0)
		<< readFile(dir.file("grid.log"));
	auto firstScan = [&](const std::string& rawlog) {
		hslam::io::CRawlogReader reader(rawlog);
		hslam::io::TRawlogEntry entry;
		while (reader.next(entry))
			if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(entry.observation))
				return scan;
		return mrpt::obs::CObservation2DRangeScan::Ptr();
	};
	const auto a = firstScan(dir.file("scene/sim.rawlog")), b = firstScan(dir.file("grid/sim.rawlog"));
	ASSERT_TRUE(a && b);
	ASSERT_EQ(a->getScanSize(), b->getScanSize());
	int compared = 0, agreed = 0;
	for (size_t i = 0; i < a->getScanSize(); ++i)
	{
		if (!a->getScanRangeValidity(i) || !b->getScanRangeValidity(i)) continue;
		++compared;
		// 5 cm cells are fatter than the zero-thickness walls: a beam grazing a
		// wall's free end may hit its cell.
		if (std::abs(a->getScanRange(i) - b->getScanRange(i)) < 0.1) ++agreed;
	}
	EXPECT_GT(compared, 120);
	EXPECT_GE(agreed, compared - 2);
}

TEST(SimApp, CommittedSamplesAreRegeneratedBitForBit)
{
	// rawlog_samples/ must be what scripts/make-samples.sh produces from
	// config_ini/sim-*.ini; if the simulator changed on purpose, rerun that script.
	hslam::testing::CTempDir dir;
	for (const std::string name : {"lab", "floor"})
	{
		ASSERT_EQ(simulate(sampleIni(name), dir.file(name), ""), 0) << readFile(dir.file(name + ".log"));
		const std::string committed = std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/" + name + "/";
		for (const char* f : {"sim.rawlog", "ground_truth.tum", "corners.csv", "waypoints.csv"})
			EXPECT_TRUE(readFile(dir.file(name + "/" + f)) == readFile(committed + f))
				<< name << "/" << f << " differs from the committed sample: run scripts/make-samples.sh";
	}
}

TEST(SimApp, BadConfigAndSceneGiveClearErrors)
{
	hslam::testing::CTempDir dir;
	EXPECT_NE(simulate(sampleIni("lab"), dir.file("o"), "--set laser.rate_hz=-3"), 0);
	EXPECT_NE(readFile(dir.file("o.log")).find("[laser] rate_hz"), std::string::npos) << readFile(dir.file("o.log"));
	std::ofstream(dir.file("bad.scene")) << "room 0 0 5 0 5 5 0 5\nchair 1 1 0 0.4 nope\n";
	EXPECT_NE(simulate(sampleIni("lab"), dir.file("p"), "--set world.scene_file=" + dir.file("bad.scene")), 0);
	EXPECT_NE(readFile(dir.file("p.log")).find("bad.scene:2:"), std::string::npos) << readFile(dir.file("p.log"));
}

TEST(SimApp, HslamProcessRunsOnASampleAndIsScored)
{
	hslam::testing::CTempDir dir;
	ASSERT_EQ(simulate(sampleIni("corridor"), dir.file("sim"), "--set simulation.duration_s=40"), 0);
	const std::string process = std::string(HSLAM_BIN_DIR) + "/hslam-process -q -c " + HSLAM_SOURCE_DIR +
								"/config_ini/hslam-default.ini -i " + dir.file("sim/sim.rawlog") + " -o " +
								dir.file("out") + " >" + dir.file("process.log") + " 2>&1";
	ASSERT_EQ(hslam::testing::runCommand(process), 0) << readFile(dir.file("process.log"));
	const std::string evaluate = std::string(HSLAM_BIN_DIR) + "/hslam-evaluate " + dir.file("sim/ground_truth.tum") +
								 " " + dir.file("out/trajectory.tum") + " --json " + dir.file("eval.json") + " >" +
								 dir.file("eval.txt") + " 2>&1";
	ASSERT_EQ(hslam::testing::runCommand(evaluate), 0) << readFile(dir.file("eval.txt"));
	const std::string json = readFile(dir.file("eval.json"));
	// Odometry-only estimate vs. the simulator's truth: 24 m of corridor with
	// Ed = 1.0003, Eb = 1.003 and wheel slip; ATE of a few cm to decimetres, not zero, not metres.
	const auto pos = json.find("\"ate_rmse_m\"");
	ASSERT_NE(pos, std::string::npos) << json;
	const double rmse = std::stod(json.substr(json.find(':', pos) + 1));
	EXPECT_GT(rmse, 0.001);
	EXPECT_LT(rmse, 0.5);
	EXPECT_EQ(hslam::common::readTumFile(dir.file("out/trajectory.tum")).size(), 400u);
}
