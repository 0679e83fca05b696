/* hslam sim: navigation scenarios (see nav_scenarios.h). */
#include <hslam/sim/free_space.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <stdexcept>

namespace hslam::sim
{
TSimulatorConfig closedLoopConfig(const mrpt::math::TPose2D& start, unsigned seed)
{
	TSimulatorConfig c;
	c.simulation.seed = seed;
	c.simulation.duration_s = 0;
	c.simulation.max_duration_s = 1e5;
	c.path.mode = "external";
	c.robot.start_x_m = start.x;
	c.robot.start_y_m = start.y;
	c.robot.start_yaw_rad = start.phi;
	return c;
}

std::vector<TNavScenario> thesisTrials(const std::string& dir)
{
	const std::string scene = (std::filesystem::path(dir) / "nav-lab.scene").string();
	const mrpt::math::TPose2D s(2.0, 2.2, 0.0);
	auto at = [&](double dx, double dy) { return mrpt::math::TPoint2D(s.x + dx, s.y + dy); };
	return {{"lab", scene, s, {at(-0.5, 0.5)}}, {"lab", scene, s, {at(-0.5, 3.0)}}, {"lab", scene, s, {at(0.1, 3.5)}}};
}

namespace
{
/** Random pairs of free points of a world (static geometry), fixed seed;
 * `freeSeeds` are points known to lie in the world's free space, one per
 * region whose connection is narrower than 2 min_clearance_m (the doorway's
 * 0.9 m door cuts its free space at 0.6 m clearance into two rooms). */
std::vector<TNavScenario> drawPairs(const std::string& name, const std::string& scene, const TScenarioDrawOptions& o,
									unsigned seed, const std::vector<mrpt::math::TPoint2D>& freeSeeds,
									bool (*accept)(const mrpt::math::TPoint2D&, const mrpt::math::TPoint2D&))
{
	const TScene sc = loadSceneFile(scene);
	std::vector<mrpt::math::TPoint2D> cells;
	std::vector<CFreeSpaceGrid> regions;
	for (const auto& freeSeed : freeSeeds)
	{
		if (std::any_of(regions.begin(), regions.end(), [&](const auto& r) { return r.isFree(freeSeed); })) continue;
		regions.emplace_back(sc.world, freeSeed, o.min_clearance_m);
		const auto more = regions.back().freeCells();
		cells.insert(cells.end(), more.begin(), more.end());
	}
	if (cells.empty()) throw std::runtime_error(scene + ": no free space around the seed point");
	std::mt19937_64 rng(seed);
	std::uniform_int_distribution<size_t> pick(0, cells.size() - 1);
	std::uniform_real_distribution<double> uphi(-M_PI, M_PI);
	std::vector<TNavScenario> out;
	for (int tries = 0; static_cast<int>(out.size()) < o.pairs_per_world && tries < 100000; ++tries)
	{
		const auto a = cells[pick(rng)], t = cells[pick(rng)];
		const double d = std::hypot(t.x - a.x, t.y - a.y);
		if (d < o.min_distance_m || d > o.max_distance_m || (accept && !accept(a, t))) continue;
		out.push_back({name, scene, mrpt::math::TPose2D(a.x, a.y, uphi(rng)), {t}});
	}
	return out;
}

bool acrossTheDoor(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& t)
{
	return (a.x < 4.8 && t.x > 5.3) || (a.x > 5.3 && t.x < 4.8);
}

bool notInsideTheU(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& t)
{
	auto inside = [](const mrpt::math::TPoint2D& p) { return p.x > 3.5 && p.x < 6.0 && p.y > 2.5 && p.y < 5.5; };
	return !inside(a) && !inside(t);
}
}  // namespace

std::vector<TNavScenario> benchmarkScenarios(const std::string& dir, const TScenarioDrawOptions& o)
{
	auto path = [&](const char* f) { return (std::filesystem::path(dir) / f).string(); };
	std::vector<TNavScenario> all;
	auto add = [&](std::vector<TNavScenario> v) { all.insert(all.end(), v.begin(), v.end()); };
	add(drawPairs("lab", path("nav-lab.scene"), o, o.seed + 1, {{1.0, 1.0}}, nullptr));
	add(drawPairs("floor", path("floor.scene"), o, o.seed + 2, {{1.25, 1.25}}, nullptr));
	add(drawPairs("cluttered", path("nav-cluttered.scene"), o, o.seed + 3, {{0.7, 0.7}}, nullptr));
	add(drawPairs("doorway", path("nav-doorway.scene"), o, o.seed + 4, {{1.0, 1.0}, {9.0, 4.5}}, acrossTheDoor));
	// U-trap: the hand-placed crossings (start west facing the U's mouth,
	// target east behind its base), then random pairs.
	const std::string u = path("nav-utrap.scene");
	for (double y : {3.2, 4.0, 4.8})
		all.push_back({"utrap", u, mrpt::math::TPose2D(1.5, y, 0.0), {{8.5, 8.0 - y}}});
	TScenarioDrawOptions rest = o;
	rest.pairs_per_world = std::max(0, o.pairs_per_world - 3);
	add(drawPairs("utrap", u, rest, o.seed + 5, {{1.0, 1.0}}, notInsideTheU));
	return all;
}

}  // namespace hslam::sim
