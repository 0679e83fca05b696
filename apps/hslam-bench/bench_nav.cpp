/* hslam-bench nav: our subsumption controller (libs/nav, thesis 4.2) against
 * MRPT 2.5's reactive navigator (CReactiveNavigationSystem, stock
 * reactive2d_config.ini, holonomic methods ND / VFF / FullEval) in the same
 * run, on the same start/target pairs (sim::benchmarkScenarios: lab with
 * walking people, office floor, cluttered room, doorway, U-trap), each driving
 * our simulated P3-DX through sim::runClosedLoop (same sensors, same control
 * period, same scoring). Per method: success rate, collisions with static
 * obstacles (contacts by walking people apart), path length over the shortest
 * collision-free path (8-connected Dijkstra on sim::CFreeSpaceGrid), time to
 * target, minimum clearance, CPU per control step; then per world; then
 * key=value lines. Progress on stderr. */
#include <hslam/common/command_line.h>
#include <hslam/common/data_paths.h>
#include <hslam/common/version.h>
#include <hslam/io/csv_line.h>
#include <hslam/sim/CMrptReactiveDriver.h>
#include <hslam/sim/CSubsumptionDriver.h>
#include <hslam/sim/free_space.h>
#include <hslam/sim/nav_scenarios.h>
#include <hslam/sim/scene.h>
#include "bench_common.h"
#include "bench_nav_trace.h"
#include "bench_report.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace hslam::bench
{
namespace
{
struct TNavBenchOptions
{
	std::string scene_dir = "config_ini/sim-worlds";
	std::string mrpt_config = sim::kMrptReactive2dConfig;
	std::string ptg_cache_dir;  //!< empty: <temp>/hslam-mrpt-ptg-cache
	sim::TScenarioDrawOptions draw;
	sim::TClosedLoopOptions loop;
	std::vector<std::string> methods{"ours", "mrpt_nd", "mrpt_vff", "mrpt_fulleval"};
	std::vector<std::string> worlds;  //!< empty: every world
	bool mrpt_raw_scan = false;  //!< hand MRPT the latest scan as is (TMrptReactiveOptions::compensate_scan_age)
	bool mrpt_reverse = false;
	double mrpt_max_speed_mps = 0;  //!< > 0: MRPT's speed limits to this (TMrptReactiveOptions::max_speed_mps)
	bool mrpt_sonar = false;  //!< sonar echoes as points for MRPT too (TMrptReactiveOptions::use_sonar)  //!< keep the stock config's backward PTG (TMrptReactiveOptions::forward_ptgs_only)
	double shortest_path_clearance_m = 0.2;  //!< the collision radius: the shortest path a disc robot can take
	std::string trace_dir;  //!< non-empty: path PNG per run (+ per-step CSV for ours), bench_nav_trace.h
	nav::TSubsumptionOptions ours;  //!< our controller's options (--ours-config; default: libs/nav defaults)
	std::string ours_config;  //!< the INI they came from, empty: defaults
};

/** One closed-loop run of one method on one pair. */
struct TNavRun
{
	std::string method, world;
	sim::TClosedLoopResult result;
	double final_distance_m = 0, shortest_m = NAN;
	mrpt::math::TPose2D start, end;
	mrpt::math::TPoint2D target;
	bool success = false;
};

std::string holonomicMethod(const std::string& method)
{
	if (method == "mrpt_nd") return "CHolonomicND";
	if (method == "mrpt_vff") return "CHolonomicVFF";
	if (method == "mrpt_fulleval") return "CHolonomicFullEval";
	throw std::invalid_argument("unknown method '" + method + "' (ours, mrpt_nd, mrpt_vff, mrpt_fulleval)");
}

std::string readText(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot read");
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

std::unique_ptr<sim::IClosedLoopController> makeController(const std::string& method, const sim::TNavScenario& s,
														   const TNavBenchOptions& o, const std::string& mrptIni,
														   double clockOrigin_s)
{
	if (method == "ours")
	{
		if (!o.trace_dir.empty()) return std::make_unique<CTracingSubsumptionDriver>(o.ours, s.targets);
		return std::make_unique<sim::CSubsumptionDriver>(o.ours, s.targets);
	}
	sim::TMrptReactiveOptions m;
	m.holonomic_method = holonomicMethod(method);
	m.ptg_cache_dir = o.ptg_cache_dir;
	m.forward_ptgs_only = !o.mrpt_reverse;
	m.footprint_min_radius_m = o.loop.collision_radius_m;
	m.compensate_scan_age = !o.mrpt_raw_scan;
	m.use_sonar = o.mrpt_sonar;
	m.max_speed_mps = o.mrpt_max_speed_mps;
	return std::make_unique<sim::CMrptReactiveDriver>(mrptIni, m, s.targets.back(), clockOrigin_s);
}

TNavRun runOne(const std::string& method, const sim::TNavScenario& s, const sim::TScene& scene,
			   const TNavBenchOptions& o, const std::string& mrptIni, size_t pairIndex)
{
	const auto config = sim::closedLoopConfig(s.start, 1);
	sim::CSimulator simulator(config, scene);
	auto controller = makeController(method, s, o, mrptIni, config.simulation.start_time_s);
	TNavRun run;
	run.method = method, run.world = s.world;
	run.result = sim::runClosedLoop(simulator, *controller, o.loop);
	const auto end = simulator.robot().truePose();
	run.final_distance_m = std::hypot(end.x - s.targets.back().x, end.y - s.targets.back().y);
	run.start = s.start;
	run.target = s.targets.back();
	run.end = end;
	run.success = run.result.success() && run.final_distance_m < 0.25;
	if (!o.trace_dir.empty())
	{
		const auto* tracing = dynamic_cast<const CTracingSubsumptionDriver*>(controller.get());
		writeNavTrace(o.trace_dir, mrpt::format("%02zu-%s-%s", pairIndex + 1, s.world.c_str(), method.c_str()), scene,
					  s, run.result, tracing ? tracing->steps : std::vector<TNavTraceStep>());
	}
	return run;
}

std::string outcome(const TNavRun& r)
{
	std::ostringstream ss;
	ss << std::fixed << std::setprecision(1);
	if (r.success) ss << "reached in " << r.result.time_s << " s, path " << r.result.path_length_m << " m";
	else if (r.result.collided)
		ss << "COLLISION at " << r.result.time_s << " s at (" << std::setprecision(2) << r.end.x << ", " << r.end.y
		   << ", " << std::setprecision(0) << r.end.phi * 180 / M_PI << " deg)" << std::setprecision(1);
	else if (r.result.timed_out) ss << "timeout, " << r.final_distance_m << " m short";
	else if (r.result.failed) ss << "gave up at " << r.result.time_s << " s, " << r.final_distance_m << " m short";
	else ss << "stopped " << r.final_distance_m << " m from the target";
	if (r.result.person_contacts) ss << " (" << r.result.person_contacts << " person contacts)";
	ss << std::setprecision(2) << "  [start " << r.start.x << " " << r.start.y << " " << std::setprecision(0)
	   << r.start.phi * 180 / M_PI << " deg, target " << std::setprecision(2) << r.target.x << " " << r.target.y
	   << "]";
	return ss.str();
}

/** Every method on every pair; the shortest path is computed once per pair. */
std::vector<TNavRun> runAll(const std::vector<sim::TNavScenario>& pairs, const TNavBenchOptions& o)
{
	const std::string mrptIni = readText(o.mrpt_config);
	std::map<std::string, sim::TScene> scenes;
	std::map<std::string, std::unique_ptr<sim::CFreeSpaceGrid>> free;
	std::vector<TNavRun> runs;
	for (size_t i = 0; i < pairs.size(); ++i)
	{
		const auto& s = pairs[i];
		if (!scenes.count(s.scene_file)) scenes[s.scene_file] = sim::loadSceneFile(s.scene_file);
		const auto& scene = scenes[s.scene_file];
		auto& grid = free[s.scene_file];
		if (!grid) grid = std::make_unique<sim::CFreeSpaceGrid>(scene.world, mrpt::math::TPoint2D(s.start.x, s.start.y),
																 o.shortest_path_clearance_m);
		const double shortest = grid->shortestPath_m({s.start.x, s.start.y}, s.targets.back());
		for (const auto& m : o.methods)
		{
			runs.push_back(runOne(m, s, scene, o, mrptIni, i));
			runs.back().shortest_m = shortest;
			std::cerr << "[" << i + 1 << "/" << pairs.size() << "] " << s.world << " " << m << ": "
					  << outcome(runs.back()) << "\n";
		}
	}
	return runs;
}

/** Figures of one method over a set of runs. */
struct TNavStats
{
	int runs = 0, successes = 0, collisions = 0, person_contacts = 0, timeouts = 0, gave_up = 0;
	double path_ratio = NAN, time_s = NAN, min_clearance_m = NAN, median_min_clearance_m = NAN, cpu_ms = NAN;
	double successRate() const { return runs ? double(successes) / runs : 0; }
};

double mean(const std::vector<double>& v)
{
	if (v.empty()) return NAN;
	double s = 0;
	for (double x : v) s += x;
	return s / v.size();
}

double median(std::vector<double> v)
{
	if (v.empty()) return NAN;
	std::sort(v.begin(), v.end());
	return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

TNavStats statsOf(const std::vector<TNavRun>& runs, const std::string& method, const std::string& world = "")
{
	TNavStats st;
	std::vector<double> ratio, time, clearance;
	double cpu = 0, steps = 0;
	for (const auto& r : runs)
	{
		if (r.method != method || (!world.empty() && r.world != world)) continue;
		++st.runs;
		st.successes += r.success;
		st.collisions += r.result.collided;
		st.person_contacts += r.result.person_contacts;
		st.timeouts += r.result.timed_out;
		st.gave_up += r.result.failed;
		clearance.push_back(r.result.min_static_clearance_m);
		cpu += r.result.cpu_s;
		steps += r.result.control_steps;
		if (!r.success) continue;
		if (std::isfinite(r.shortest_m) && r.shortest_m > 0) ratio.push_back(r.result.path_length_m / r.shortest_m);
		time.push_back(r.result.time_s);
	}
	st.path_ratio = mean(ratio);
	st.time_s = mean(time);
	st.min_clearance_m = clearance.empty() ? NAN : *std::min_element(clearance.begin(), clearance.end());
	st.median_min_clearance_m = median(clearance);
	st.cpu_ms = steps ? 1e3 * cpu / steps : NAN;
	return st;
}

std::vector<std::string> methodRow(const std::string& method, const TNavStats& s)
{
	const auto count = [](int n) { return std::to_string(n); };
	return {method,
			count(s.successes) + "/" + count(s.runs) + " (" + fixed(100 * s.successRate(), 0) + " %)",
			count(s.collisions),
			count(s.person_contacts),
			count(s.timeouts) + " / " + count(s.gave_up),
			fixed(s.path_ratio, 2),
			fixed(s.time_s, 1) + " s",
			fixed(s.min_clearance_m, 2) + " / " + fixed(s.median_min_clearance_m, 2) + " m",
			fixed(s.cpu_ms, 2) + " ms"};
}

void printMethodTable(const std::vector<TNavRun>& runs, const TNavBenchOptions& o)
{
	std::cout << "\n";
	const CMarkdownTable table(std::cout, {"method", "success", "collisions (static)", "person contacts",
										   "timeouts / gave up", "path / shortest", "time to target",
										   "min clearance to static obstacles (worst / median)", "CPU / control step"});
	table.printHeader();
	for (const auto& m : o.methods) table.printRow(methodRow(m, statsOf(runs, m)));
	std::cout << "(path / shortest and time: means over the successful runs; shortest: 8-connected path keeping "
			  << fixed(o.shortest_path_clearance_m, 2) << " m from static obstacles)\n";
}

std::vector<std::string> worldsOf(const std::vector<sim::TNavScenario>& pairs)
{
	std::vector<std::string> w;
	for (const auto& s : pairs)
		if (std::find(w.begin(), w.end(), s.world) == w.end()) w.push_back(s.world);
	return w;
}

void printWorldTable(const std::vector<TNavRun>& runs, const std::vector<std::string>& worlds,
					 const TNavBenchOptions& o)
{
	std::cout << "\nsuccess (collisions) per world:\n\n";
	std::vector<std::string> headers{"world"};
	headers.insert(headers.end(), o.methods.begin(), o.methods.end());
	const CMarkdownTable table(std::cout, headers);
	table.printHeader();
	for (const auto& w : worlds)
	{
		std::vector<std::string> cells{w};
		for (const auto& m : o.methods)
		{
			const auto s = statsOf(runs, m, w);
			cells.push_back(std::to_string(s.successes) + "/" + std::to_string(s.runs) + " (" +
							std::to_string(s.collisions) + ")");
		}
		table.printRow(cells);
	}
}

void printKeyValues(const std::vector<TNavRun>& runs, const std::vector<std::string>& worlds,
					const TNavBenchOptions& o, size_t pairs)
{
	std::cout << "\n";
	CKeyValueLines keys(std::cout, 4);
	keys("nav_pairs", pairs)("nav_worlds", worlds.size());
	double best = -1;
	std::string bestMethod = "none";
	for (const auto& m : o.methods)
	{
		const auto s = statsOf(runs, m);
		if (m != "ours" && s.successRate() > best) best = s.successRate(), bestMethod = m;
		keys("nav_success_rate_" + m, s.successRate())("nav_collisions_" + m, s.collisions)(
			"nav_person_contacts_" + m, s.person_contacts)("nav_timeouts_" + m, s.timeouts)(
			"nav_gave_up_" + m, s.gave_up)("nav_path_ratio_" + m, s.path_ratio)("nav_time_to_target_s_" + m, s.time_s)(
			"nav_min_clearance_m_" + m, s.min_clearance_m)("nav_cpu_ms_per_step_" + m, s.cpu_ms);
		for (const auto& w : worlds) keys("nav_success_rate_" + m + "_" + w, statsOf(runs, m, w).successRate());
	}
	if (best < 0) return;
	keys("nav_success_rate_mrpt_best", best)("nav_mrpt_best_method", bestMethod);
	// CPU per control step of ours over that of MRPT's best method (the one above).
	if (std::find(o.methods.begin(), o.methods.end(), "ours") != o.methods.end())
		keys("nav_cpu_ratio_ours_vs_mrpt_best", statsOf(runs, "ours").cpu_ms / statsOf(runs, bestMethod).cpu_ms);
}

nav::TSubsumptionOptions loadOursConfig(const std::string& path)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": not found");
	return nav::TSubsumptionOptions::load(mrpt::config::CConfigFile(path));
}

/** One cache folder per PTG set (MRPT names its grid files by PTG index only). */
std::string ptgCacheDir(const TNavBenchOptions& o, const std::string& given)
{
	const std::string base = given.empty() ? (fs::temp_directory_path() / "hslam-mrpt-ptg-cache").string() : given;
	return base + std::string(o.mrpt_reverse ? "/all-ptgs" : "/forward-ptgs") +
		   (o.mrpt_max_speed_mps > 0 ? mrpt::format("-v%.2f", o.mrpt_max_speed_mps) : std::string());
}

std::vector<std::string> methodList(const std::string& commaList)
{
	std::vector<std::string> out;
	for (const auto& m : io::splitCsvLine(commaList))
	{
		if (m.empty()) continue;
		if (m != "ours") holonomicMethod(m);  // throws on an unknown name
		out.push_back(m);
	}
	return out;
}

TNavBenchOptions parseOptions(int argc, char** argv, bool& help)
{
	TCLAP::CmdLine cmd("hslam-bench nav: our subsumption controller vs MRPT's reactive navigator (ND, VFF, FullEval) "
					   "on sim::benchmarkScenarios",
					   ' ', common::versionText());
	TCLAP::UnlabeledValueArg<std::string> suite("suite", "nav", true, "", "suite", cmd);
	TCLAP::ValueArg<int> perWorld("", "pairs-per-world", "start/target pairs per world (default 13)", false, 13, "N", cmd);
	TCLAP::ValueArg<double> timeout("", "timeout", "simulated seconds per run (default 180)", false, 180, "s", cmd);
	TCLAP::ValueArg<std::string> methods("", "methods", "comma list of ours, mrpt_nd, mrpt_vff, mrpt_fulleval (default all)",
										 false, "ours,mrpt_nd,mrpt_vff,mrpt_fulleval", "list", cmd);
	TCLAP::ValueArg<std::string> worlds("", "worlds", "comma list of worlds to run (default all: lab, floor, cluttered, doorway, utrap)",
										false, "", "list", cmd);
	TCLAP::ValueArg<std::string> scenes("", "scenes", "folder of the nav-*.scene worlds (default config_ini/sim-worlds)",
										false, "config_ini/sim-worlds", "dir", cmd);
	TCLAP::ValueArg<std::string> mrptConfig("", "mrpt-config", "MRPT reactive INI (default: the stock reactive2d_config.ini)",
											false, sim::kMrptReactive2dConfig, "file.ini", cmd);
	TCLAP::ValueArg<std::string> cache("", "ptg-cache", "folder for MRPT's PTG collision-grid cache (default <tmp>/hslam-mrpt-ptg-cache)",
									   false, "", "dir", cmd);
	TCLAP::SwitchArg reverse("", "mrpt-reverse", "keep the stock config's backward PTG (K = -1; default: forward PTGs only, "
							 "the P3-DX senses ahead only)", cmd);
	TCLAP::SwitchArg rawScan("", "mrpt-raw-scan", "hand MRPT the latest scan in the robot frame of its own time "
							 "(default: moved into the current robot frame)", cmd);
	TCLAP::SwitchArg sonar("", "mrpt-sonar", "MRPT senses sonar echoes (as points on the cone axes) besides the laser "
						   "(default: the laser only)", cmd);
	TCLAP::ValueArg<double> maxSpeed("", "mrpt-max-speed", "MRPT's robotMax_V_mps and PTG v_max (m/s; default: the config's, stock 1.0)",
									 false, 0, "m/s", cmd);
	TCLAP::ValueArg<std::string> trace("", "trace", "write DIR/NN-world-method.png (path over the world; ours: coloured by "
									   "the layer that steered) and, for ours, .csv (every control step)",
									   false, "", "DIR", cmd);
	TCLAP::ValueArg<std::string> oursConfig("", "ours-config", "our controller's INI (config_ini/nav-subsumption.ini "
											"format; default: the libs/nav defaults)", false, "", "file.ini", cmd);
	TCLAP::ValueArg<unsigned> seed("", "seed", "seed of the drawn start/target pairs (default 2016; the U-trap's "
								   "hand-placed crossings stay)", false, 2016, "N", cmd);
	TNavBenchOptions o;
	help = !cmd.parse(argc, argv);
	o.draw.pairs_per_world = std::max(1, perWorld.getValue());
	o.loop.timeout_s = timeout.getValue();
	o.scene_dir = common::resolveDataFile(scenes.getValue());
	o.mrpt_config = mrptConfig.getValue();
	o.mrpt_reverse = reverse.getValue();
	o.mrpt_raw_scan = rawScan.getValue();
	o.mrpt_sonar = sonar.getValue();
	o.mrpt_max_speed_mps = maxSpeed.getValue();
	o.trace_dir = trace.getValue();
	o.draw.seed = seed.getValue();
	o.ours_config = oursConfig.getValue();
	if (!o.ours_config.empty()) o.ours = loadOursConfig(o.ours_config);
	o.ptg_cache_dir = ptgCacheDir(o, cache.isSet() ? cache.getValue() : std::string());
	for (const auto& w : io::splitCsvLine(worlds.getValue()))
		if (!w.empty()) o.worlds.push_back(w);
	o.methods = methodList(methods.getValue());
	return o;
}
}  // namespace

int runNavSuite(int argc, char** argv)
{
	bool help = false;
	const auto o = parseOptions(argc, argv, help);
	if (help) return common::exitCodeAfterParseStop(argc, argv);
	fs::create_directories(o.ptg_cache_dir);
	auto pairs = sim::benchmarkScenarios(o.scene_dir, o.draw);
	if (!o.worlds.empty())
		pairs.erase(std::remove_if(pairs.begin(), pairs.end(), [&](const sim::TNavScenario& s)
								   { return std::find(o.worlds.begin(), o.worlds.end(), s.world) == o.worlds.end(); }),
					pairs.end());
	const auto worlds = worldsOf(pairs);
	std::cout << "Suite nav: " << pairs.size() << " start/target pairs in " << worlds.size() << " worlds, "
			  << o.methods.size() << " methods, timeout " << o.loop.timeout_s << " s (simulated), control period "
			  << o.loop.control_period_s << " s, collision radius " << o.loop.collision_radius_m << " m\n"
			  << "ours: " << (o.ours_config.empty() ? std::string("libs/nav defaults") : o.ours_config)
			  << " (target seeking <= 0.3 m/s, eq. 33); seed " << o.draw.seed << "; MRPT: " << o.mrpt_config
			  << " (holonomic parameters as shipped, speed limits "
			  << (o.mrpt_max_speed_mps > 0 ? mrpt::format("%.2f m/s", o.mrpt_max_speed_mps) : std::string("as shipped"))
			  << "), P3-DX footprint within the collision disc, "
			  << (o.mrpt_reverse ? "all PTGs (backward one included)" : "forward PTGs only") << ", "
			  << (o.mrpt_sonar ? "laser + sonar echoes" : "laser only") << ", "
			  << (o.mrpt_raw_scan ? "obstacles in the frame they were sensed in" : "obstacles moved into the current robot frame")
			  << ", target reached within 0.2 m\n";
	const auto runs = runAll(pairs, o);
	printMethodTable(runs, o);
	printWorldTable(runs, worlds, o);
	printKeyValues(runs, worlds, o, pairs.size());
	return 0;
}
}  // namespace hslam::bench
