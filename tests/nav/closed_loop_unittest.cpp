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
