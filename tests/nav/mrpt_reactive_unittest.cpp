/* hslam tests: MRPT 2.5's CReactiveNavigationSystem (stock reactive2d_config.ini,
 * holonomic methods ND / VFF / FullEval) driving our simulated P3-DX through
 * CMrptReactiveDriver / CSimRobot2NavInterface: the peer of hslam-bench nav
 * must reach an open target, else the adapter (frames, units, time) is wrong. */
#include <gtest/gtest.h>
#include <hslam/sim/CMrptReactiveDriver.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/Clock.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRange.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hslam;

namespace
{
std::string stockConfig()
{
	std::ifstream f(sim::kMrptReactive2dConfig);
	EXPECT_TRUE(f.good()) << sim::kMrptReactive2dConfig;
	std::stringstream ini;
	ini << f.rdbuf();
	return ini.str();
}

struct TRun
{
	sim::TClosedLoopResult result;
	double final_distance_m = 0;
};

TRun driveMrpt(const std::string& method, const std::string& sceneText, const mrpt::math::TPose2D& start,
			   const mrpt::math::TPoint2D& target)
{
	sim::TMrptReactiveOptions o;
	o.holonomic_method = method;
	// One folder per test: ctest may run tests in parallel and MRPT names its grid files by PTG index only.
	o.ptg_cache_dir = std::string(HSLAM_BINARY_DIR) + "/mrpt-ptg-cache/" +
					  ::testing::UnitTest::GetInstance()->current_test_info()->name();
	std::filesystem::create_directories(o.ptg_cache_dir);
	const auto config = sim::closedLoopConfig(start, 1);
	sim::CSimulator simulator(config, sim::parseSceneText(sceneText, "test"));
	sim::CMrptReactiveDriver driver(stockConfig(), o, target, config.simulation.start_time_s);
	sim::TClosedLoopOptions loop;
	loop.timeout_s = 60;
	TRun run{sim::runClosedLoop(simulator, driver, loop)};
	const auto end = simulator.robot().truePose();
	run.final_distance_m = std::hypot(end.x - target.x, end.y - target.y);
	return run;
}

const char* kOpenRoom = "room 0 0 8 0 8 6 0 6\n";
}  // namespace

TEST(MrptReactive, EveryHolonomicMethodReachesAnOpenTargetWithoutCollision)
{
	const mrpt::math::TPose2D start(1.5, 1.5, 0.0);
	const mrpt::math::TPoint2D target(6.0, 4.0);
	const double straight = std::hypot(target.x - start.x, target.y - start.y);
	for (const char* method : {"CHolonomicND", "CHolonomicVFF", "CHolonomicFullEval"})
	{
		const auto run = driveMrpt(method, kOpenRoom, start, target);
		const auto& r = run.result;
		EXPECT_TRUE(r.finished) << method << " failed=" << r.failed << " timed_out=" << r.timed_out;
		EXPECT_FALSE(r.collided) << method << " min clearance " << r.min_clearance_m;
		EXPECT_LT(run.final_distance_m, 0.3) << method;
		EXPECT_GT(r.path_length_m, straight - 0.3) << method;
		EXPECT_LT(r.path_length_m, 1.5 * straight) << method << ": no wandering";
		EXPECT_LT(r.time_s, 30.0) << method << " (simulated time)";
	}
}

TEST(MrptReactive, GoesAroundABoxOnTheStraightLine)
{
	const std::string scene = std::string(kOpenRoom) + "box 4.0 3.0 1.0 1.0\n";
	const auto run = driveMrpt("CHolonomicND", scene, {1.5, 3.0, 0.0}, {6.5, 3.0});
	EXPECT_TRUE(run.result.finished);
	EXPECT_FALSE(run.result.collided) << "min clearance " << run.result.min_clearance_m;
	EXPECT_LT(run.final_distance_m, 0.3);
	EXPECT_GT(run.result.path_length_m, 5.0 - 0.3);
	EXPECT_GT(run.result.min_clearance_m, 0.2);
}

TEST(MrptReactive, RejectsAnUnknownHolonomicMethod)
{
	sim::TMrptReactiveOptions o;
	o.holonomic_method = "CHolonomicXYZ";
	EXPECT_THROW(sim::mrptReactiveConfig("[x]\na=1\n", o), std::invalid_argument);
}

TEST(MrptReactive, ConfigKeepsTheForwardPtgsAndTheP3dxFootprint)
{
	sim::TMrptReactiveOptions o;
	o.holonomic_method = "CHolonomicVFF";
	const mrpt::config::CConfigFileMemory cfg(sim::mrptReactiveConfig(stockConfig(), o));
	EXPECT_EQ(cfg.read_string("CAbstractPTGBasedReactive", "holonomic_method", ""), "CHolonomicVFF");
	EXPECT_EQ(cfg.read_int("CReactiveNavigationSystem", "PTG_COUNT", 0), 2);  // stock: 3, the third with K = -1
	EXPECT_EQ(cfg.read_string("CReactiveNavigationSystem", "PTG0_Type", ""), "CPTG_DiffDrive_C");
	EXPECT_DOUBLE_EQ(cfg.read_double("CReactiveNavigationSystem", "PTG0_K", 0), 1.0);
	EXPECT_EQ(cfg.read_string("CReactiveNavigationSystem", "PTG1_Type", ""), "CPTG_DiffDrive_alpha");
	std::vector<double> xs, ys;
	cfg.read_vector("CReactiveNavigationSystem", "RobotModel_shape2D_xs", std::vector<double>(), xs, true);
	cfg.read_vector("CReactiveNavigationSystem", "RobotModel_shape2D_ys", std::vector<double>(), ys, true);
	ASSERT_EQ(xs.size(), 4u);
	ASSERT_EQ(ys.size(), 4u);
	EXPECT_NEAR(xs[1] - xs[0], 0.4625, 1e-9);  // 262.5 mm ahead, 200 mm behind (the 0.2 m collision disc)
	EXPECT_NEAR(ys[0] - ys[2], 0.4, 1e-9);  // 381 mm widened to the 0.4 m disc
	o.forward_ptgs_only = false;
	const mrpt::config::CConfigFileMemory stock(sim::mrptReactiveConfig(stockConfig(), o));
	EXPECT_EQ(stock.read_int("CReactiveNavigationSystem", "PTG_COUNT", 0), 3);
}

TEST(MrptReactive, ObstaclesAreMovedIntoTheCurrentRobotFrame)
{
	const double origin = 1700000000.0;
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i) scan.setScanRangeValidity(i, false);
	scan.setScanRange(90, 1.0f);  // straight ahead, 1 m
	scan.setScanRangeValidity(90, true);
	scan.timestamp = mrpt::Clock::fromDouble(origin + 0.0);
	mrpt::obs::CObservationRange sonar;
	sonar.maxSensorDistance = 5;
	mrpt::obs::CObservationRange::TMeasurement m;
	m.sensorPose = mrpt::math::TPose3D(0.1, 0, 0, 0, 0, 0);
	m.sensedDistance = 0.5f;
	sonar.sensedData.push_back(m);
	sonar.timestamp = scan.timestamp;
	for (bool compensate : {true, false})
	{
		sim::CSimRobot2NavInterface robot(origin, compensate, true);
		robot.setInput({0.0, {2.0, 1.0, 0.0}, &scan, &sonar});
		robot.setInput({0.1, {2.1, 1.0, 0.0}, &scan, &sonar});  // 0.1 m ahead since both were sensed
		mrpt::maps::CSimplePointsMap obstacles;
		mrpt::system::TTimeStamp stamp;
		ASSERT_TRUE(robot.senseObstacles(obstacles, stamp));
		ASSERT_EQ(obstacles.size(), 2u);
		const double shift = compensate ? 0.1 : 0.0;
		EXPECT_NEAR(obstacles.getPointsBufferRef_x()[0], 1.0 - shift, 1e-6);  // laser
		EXPECT_NEAR(obstacles.getPointsBufferRef_y()[0], 0.0, 1e-6);
		EXPECT_NEAR(obstacles.getPointsBufferRef_x()[1], 0.6 - shift, 1e-6);  // sonar echo on its axis
		mrpt::math::TPose2D pose;
		mrpt::math::TTwist2D vel;
		mrpt::math::TPose2D odo;
		std::string frame;
		ASSERT_TRUE(robot.getCurrentPoseAndSpeeds(pose, vel, stamp, odo, frame));
		EXPECT_NEAR(vel.vx, 1.0, 1e-9);  // 0.1 m in 0.1 s
		EXPECT_NEAR(robot.getNavigationTime(), 0.1, 1e-12);
	}
}
