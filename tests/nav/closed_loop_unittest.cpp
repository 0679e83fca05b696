/* hslam tests: the subsumption controller (thesis 4.2) driving the simulated
 * P3-DX (libs/sim: LMS200 + sonar ring, walking people) in closed loop. */
#include <gtest/gtest.h>
#include <hslam/sim/CSubsumptionDriver.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>
#include <hslam/testing/test_paths.h>

#include <cmath>

using namespace hslam;

namespace
{
const std::string kScenes = std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-worlds";

sim::TClosedLoopResult drive(const sim::TNavScenario& s, unsigned seed = 1)
{
	sim::CSimulator simulator(sim::closedLoopConfig(s.start, seed), sim::loadSceneFile(s.scene_file));
	sim::CSubsumptionDriver driver(nav::TSubsumptionOptions(), s.targets);
	return sim::runClosedLoop(simulator, driver, sim::TClosedLoopOptions());
}
}  // namespace

TEST(ClosedLoop, ThesisTrialsReachTheirTargetsWithoutCollision)
{
	for (const auto& trial : sim::thesisTrials(kScenes))
	{
		const auto r = drive(trial);
		EXPECT_TRUE(r.finished) << "target " << trial.targets[0].x << " " << trial.targets[0].y;
		EXPECT_FALSE(r.collided) << "min clearance " << r.min_clearance_m;
		const auto& end = r.path.back().pose;
		EXPECT_LT(std::hypot(end.x - trial.targets[0].x, end.y - trial.targets[0].y), 0.25);
		const double straight = std::hypot(trial.targets[0].x - trial.start.x, trial.targets[0].y - trial.start.y);
		EXPECT_GE(r.path_length_m, straight - 0.2);
		EXPECT_LT(r.path_length_m, 3.0 * straight + 1.0) << "no wandering";
	}
}

TEST(ClosedLoop, PassesTheDoorwayAndVisitsATargetSequence)
{
	sim::TNavScenario s{"doorway", kScenes + "/nav-doorway.scene", {1.5, 1.5, 0.0}, {{4.0, 3.0}, {8.5, 3.0}, {8.5, 5.0}}};
	const auto r = drive(s);
	EXPECT_TRUE(r.finished);
	EXPECT_FALSE(r.collided) << "min clearance " << r.min_clearance_m;
	EXPECT_GT(r.min_clearance_m, 0.2);
	const auto& end = r.path.back().pose;
	EXPECT_LT(std::hypot(end.x - 8.5, end.y - 5.0), 0.25);
}

TEST(ClosedLoop, PassesTheDoorwayApproachedAtAnAngle)
{
	// hslam-bench nav doorway pairs (seed 2016) that approach the 0.9 m door at
	// an angle; before the explained-echo fusion and the gap candidates (docs/nav.md)
	// each timed out at 180 s, 1.0-5.9 m short, sliding along the wall past the door.
	const std::string scene = kScenes + "/nav-doorway.scene";
	const std::vector<sim::TNavScenario> pairs{
		{"doorway", scene, {0.65, 4.95, -16 * M_PI / 180}, {{7.65, 4.55}}},  // pair 1: 1.8 m short
		{"doorway", scene, {6.85, 2.45, -172 * M_PI / 180}, {{2.75, 1.45}}},  // pair 2: 4.9 m short, east to west
		{"doorway", scene, {3.55, 0.75, 143 * M_PI / 180}, {{8.55, 3.15}}},  // pair 3: 1.0 m short
		{"doorway", scene, {3.15, 1.85, 156 * M_PI / 180}, {{8.05, 3.95}}},  // pair 7: 5.9 m short
		{"doorway", scene, {4.25, 4.15, 29 * M_PI / 180}, {{6.45, 1.85}}}};  // pair 9: 4.2 m short
	for (const auto& s : pairs)
	{
		const auto r = drive(s);
		const auto& t = s.targets.back();
		const std::string what = "start " + std::to_string(s.start.x) + " " + std::to_string(s.start.y);
		EXPECT_TRUE(r.finished) << what;
		EXPECT_FALSE(r.collided) << what;
		EXPECT_LT(r.time_s, 90.0) << what << ": the door, not a tour of the rooms";
		EXPECT_GT(r.min_static_clearance_m, 0.3) << what << " (measured 0.38 m and more)";
		const auto& end = r.path.back().pose;
		EXPECT_LT(std::hypot(end.x - t.x, end.y - t.y), 0.25) << what;
	}
}
