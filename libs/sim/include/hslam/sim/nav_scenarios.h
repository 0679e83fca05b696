/* hslam sim: navigation scenarios (world + start + targets) for closed-loop
 * runs: the thesis's three MobileSim trials (4.2.2, figures 66-68) in our lab
 * world, and the start/target pairs of hslam-bench nav in six worlds (thesis
 * lab with walking people, office floor (floor.scene) with a walking person, cluttered room, U-shaped
 * trap, doorway). Pairs are drawn with a fixed seed from the free space of
 * each world (clearance >= min_clearance_m, start-target distance >=
 * min_distance_m), plus hand-placed pairs that cross the U; the doorway's
 * pairs join its two rooms, drawn from the free space of both (its 0.9 m door
 * is narrower than 2 min_clearance_m, so one seed reaches one room only). */
#pragma once

#include <hslam/sim/CSimulator.h>

#include <string>
#include <vector>

namespace hslam::sim
{
struct TNavScenario
{
	std::string world;  //!< short name (lab, floor, cluttered, utrap, doorway)
	std::string scene_file;  //!< path of the scene file
	mrpt::math::TPose2D start;
	std::vector<mrpt::math::TPoint2D> targets;
};

/** Simulator configuration for closed-loop driving (path mode external, P3-DX
 * with LMS200 and the front sonar ring, no odometry error) from `start`. */
TSimulatorConfig closedLoopConfig(const mrpt::math::TPose2D& start, unsigned seed);

/** Thesis 4.2.2 trials: start (2.0, 2.2, 0) facing the drawer of nav-lab.scene,
 * targets start + (-0.5, 0.5), (-0.5, 3.0), (0.1, 3.5) m (figures 66-68). */
std::vector<TNavScenario> thesisTrials(const std::string& sceneDir);

struct TScenarioDrawOptions
{
	int pairs_per_world = 13;
	double min_clearance_m = 0.6;
	double min_distance_m = 3.0;
	double max_distance_m = 12.0;  //!< keeps runs on the 56 m floor short
	unsigned seed = 2016;
};

/** The benchmark's start/target pairs (one target each). */
std::vector<TNavScenario> benchmarkScenarios(const std::string& sceneDir, const TScenarioDrawOptions& options = {});

}  // namespace hslam::sim
