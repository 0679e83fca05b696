/* hslam tests: MRPT 2.5's CReactiveNavigationSystem (stock reactive2d_config.ini,
 * holonomic methods ND / VFF / FullEval) driving our simulated P3-DX through
 * CMrptReactiveDriver / CSimRobot2NavInterface: the peer of hslam-bench nav
 * must reach an open target, else the adapter (frames, units, time) is wrong. */
#include <gtest/gtest.h>
#include <hslam/sim/CMrptReactiveDriver.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>
#include <hslam/testing/test_paths.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hslam;

namespace
{
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
	o.ptg_cache_dir = std::string(HSLAM_BINARY_DIR) + "/mrpt-ptg-cache";
	std::filesystem::create_directories(o.ptg_cache_dir);
	std::ifstream f(sim::kMrptReactive2dConfig);
	EXPECT_TRUE(f.good()) << sim::kMrptReactive2dConfig;
	std::stringstream ini;
	ini << f.rdbuf();
	const auto config = sim::closedLoopConfig(start, 1);
	sim::CSimulator simulator(config, sim::parseSceneText(sceneText, "test"));
	sim::CMrptReactiveDriver driver(ini.str(), o, target, config.simulation.start_time_s);
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
