/* hslam-bench graph: the cost of the loop-closure back-end (issue 13).
 *
 *   hslam-bench graph [-r RAWLOG -g GROUND_TRUTH.tum ...] [-c INI] [--out DIR] [--max-keyframes N]
 *
 * Part 1, optimisation against graph size: synthetic pose graphs of a robot
 * driving laps of a circle (60 m around, a keyframe every 0.5 m: 120 per
 * lap), sequential edges from a biased, noisy front-end (0.2 deg/keyframe of
 * heading bias, 2 cm / 0.5 deg noise) and a loop edge every 10 keyframes to
 * the same place one lap earlier (2 cm / 0.5 deg noise), up to --max-keyframes
 * (default 10 000). For each size, the state the pipeline is in when a
 * closure arrives: every keyframe up to the previous closure already
 * optimised (placed at the truth; the optimum lies within centimetres of it),
 * the 10 keyframes since then chained on by the drifting front-end. Then the
 * new closure's edge is added and the solve the pipeline runs for it is
 * timed ("per closure": CPoseGraph::optimize() over every node, with the
 * robust edge-dropping step), with our sparse solver (Eigen) and with MRPT's
 * optimize_graph_spa_levmarq in the same run.
 * The ATE of the last keyframes before and after shows the solve worked.
 *
 * Part 2, the back-end in the pipeline: each -r rawlog through hslam-process
 * with [loop_closure] enabled = false and = true (same INI otherwise),
 * whole-process CPU ms per scan of both, their ratio (issue target <= 1.5),
 * the same for wall time (the back-end runs on its own thread by default:
 * `loop_closure_wall_ratio=`), and ATE of both with a ground truth. */
#include "bench_common.h"
#include "bench_report.h"
#include "child_process.h"

#include <hslam/common/command_line.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/graph/CPoseGraph.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <random>
#include <regex>
#include <sstream>

namespace hslam::bench
{
namespace
{
namespace fs = std::filesystem;
using mrpt::math::TPose2D;

/** The synthetic lap route and the front-end's errors on it. */
struct TLapRoute
{
	double circumference_m = 60.0, keyframe_spacing_m = 0.5;
	double yaw_bias_rad = mrpt::DEG2RAD(0.2);  //!< per keyframe: the drift loop closure removes
	double xy_noise_m = 0.02, yaw_noise_rad = mrpt::DEG2RAD(0.5);
	int closure_every = 10;

	int keyframesPerLap() const { return static_cast<int>(std::lround(circumference_m / keyframe_spacing_m)); }
	TPose2D truth(int k) const
	{
		const double radius = circumference_m / (2 * M_PI), a = k * keyframe_spacing_m / radius;
		return {radius * std::sin(a), radius * (1 - std::cos(a)), mrpt::math::wrapToPi(a)};
	}
};

Eigen::Matrix3d informationOf(double xyStd_m, double yawStd_rad)
{
	return Eigen::Vector3d(1 / (xyStd_m * xyStd_m), 1 / (xyStd_m * xyStd_m), 1 / (yawStd_rad * yawStd_rad))
		.asDiagonal();
}

/** A measured relative pose: the true one plus noise (and bias). */
TPose2D measured(const TPose2D& truthRelative, const TLapRoute& route, double yawBias_rad, std::mt19937& rng)
{
	std::normal_distribution<double> xy(0, route.xy_noise_m), yaw(0, route.yaw_noise_rad);
	return {truthRelative.x + xy(rng), truthRelative.y + xy(rng), truthRelative.phi + yaw(rng) + yawBias_rad};
}

/** Adds keyframes [graph.nodeCount(), end) with their sequential edges and
 * the loop edges due among them (those of keyframes < closuresUpTo); each
 * new node is placed at the truth (`atTruth`, an optimised past) or chained
 * on the previous node by its measured edge (the front-end since then). */
void extendLaps(graph::CPoseGraph& g, const TLapRoute& route, int end, int closuresUpTo, bool atTruth,
				std::mt19937& rng)
{
	const int lap = route.keyframesPerLap();
	for (int k = static_cast<int>(g.nodeCount()); k < end; ++k)
	{
		if (k == 0)
		{
			g.addNode(0, route.truth(0));
			continue;
		}
		graph::TGraphEdge e;
		e.from = k - 1, e.to = k;
		e.relative = measured(graph::relativePose(route.truth(k - 1), route.truth(k)), route, route.yaw_bias_rad, rng);
		e.information = informationOf(route.xy_noise_m, route.yaw_noise_rad);
		g.addNode(k, atTruth ? route.truth(k) : graph::composePose(g.nodes()[k - 1].pose, e.relative));
		g.addEdge(e);
		if (k >= lap && k % route.closure_every == 0 && k < closuresUpTo)
		{
			graph::TGraphEdge loop = e;
			loop.from = k - lap, loop.kind = graph::EEdgeKind::loop;
			loop.relative = measured(graph::relativePose(route.truth(k - lap), route.truth(k)), route, 0, rng);
			g.addEdge(loop);
		}
	}
}

/** Position RMSE of the nodes [first, nodeCount()) against the truth. */
double ateOf(const graph::CPoseGraph& g, const TLapRoute& route, size_t first)
{
	double sum2 = 0;
	for (size_t k = first; k < g.nodeCount(); ++k)
	{
		const auto t = route.truth(static_cast<int>(k));
		sum2 += std::pow(g.nodes()[k].pose.x - t.x, 2) + std::pow(g.nodes()[k].pose.y - t.y, 2);
	}
	return std::sqrt(sum2 / static_cast<double>(g.nodeCount() - first));
}

/** One solver on one graph size. */
struct TGraphSizeRow
{
	int nominal = 0;  //!< the size asked for
	size_t keyframes = 0, edges = 0;
	double ate_new_before_m = 0, ate_new_after_m = 0, ate_all_after_m = 0;
	graph::TOptimizationReport per_closure;
};

TGraphSizeRow measureGraphSize(int keyframes, const TLapRoute& route, const std::string& solver)
{
	std::mt19937 rng(1234);
	graph::TPoseGraphOptions options;
	options.solver = solver;
	graph::CPoseGraph g(options);
	TGraphSizeRow row;
	row.nominal = keyframes;
	const int previous = keyframes - keyframes % route.closure_every;  // the last closure already solved
	extendLaps(g, route, previous + 1, previous + 1, true, rng);
	g.optimize();  // the optimised past (the truth is near, not at, its optimum)
	const size_t firstNew = g.nodeCount();
	const int next = previous + route.closure_every;
	extendLaps(g, route, next, next, false, rng);
	extendLaps(g, route, next + 1, next + 1, false, rng);  // the keyframe that closes the loop, and its edge
	row.ate_new_before_m = ateOf(g, route, firstNew);
	row.per_closure = g.optimize();
	row.ate_new_after_m = ateOf(g, route, firstNew);
	row.ate_all_after_m = ateOf(g, route, 0);
	row.keyframes = g.nodeCount(), row.edges = g.edges().size();
	return row;
}

/** Rows of the default solver (sparse) and its peer (MRPT's), size by size. */
void printGraphRows(const std::vector<TGraphSizeRow>& ours, const std::vector<TGraphSizeRow>& mrpt)
{
	std::cout << "\nPose-graph optimisation for one new closure (CPoseGraph::optimize), synthetic laps\n";
	const CReportTable table(std::cout, {{"keyframes", 10},
										 {"edges", 8},
										 {"sparse ms", 12},
										 {"iter", 6},
										 {"MRPT ms", 12},
										 {"iter", 6},
										 {"speedup", 10},
										 {"new 10 ATE before", 20},
										 {"after sparse", 13},
										 {"after MRPT", 11},
										 {"chi2 sparse", 12},
										 {"chi2 MRPT", 12}});
	table.printHeader();
	for (size_t k = 0; k < ours.size() && k < mrpt.size(); ++k)
	{
		const auto &r = ours[k].per_closure, &m = mrpt[k].per_closure;
		table.printRow({std::to_string(ours[k].keyframes), std::to_string(ours[k].edges), fixed(r.time_ms, 1),
						std::to_string(r.iterations), fixed(m.time_ms, 1), std::to_string(m.iterations),
						fixed(m.time_ms / r.time_ms, 1), fixed(ours[k].ate_new_before_m, 3),
						fixed(ours[k].ate_new_after_m, 3), fixed(mrpt[k].ate_new_after_m, 3), fixed(r.final_chi2, 1),
						fixed(m.final_chi2, 1)});
	}
	CKeyValueLines keys(std::cout);
	for (size_t k = 0; k < ours.size() && k < mrpt.size(); ++k)
		keys("graph_optimize_ms_at_" + std::to_string(ours[k].nominal), ours[k].per_closure.time_ms)(
			"graph_optimize_mrpt_ms_at_" + std::to_string(ours[k].nominal), mrpt[k].per_closure.time_ms);
	if (!ours.empty() && ours.back().nominal >= 10000) keys("graph_optimize_ms_at_10k", ours.back().per_closure.time_ms);
}

/** One rawlog through hslam-process with the back-end off and on. */
struct TBackendRow
{
	std::string name;
	size_t scans = 0;
	TChildTimes off, on;  //!< whole process, back-end off / on
	std::optional<double> ate_off_m, ate_on_m;
	std::string closures;  //!< the run's "closures tested: N (accepted A, rejected R)" line
	size_t keyframes = 0;  //!< the back-end's keyframes in the run with it on
};

size_t scansOf(const std::string& summaryJson)
{
	std::ifstream f(summaryJson);
	std::stringstream text;
	text << f.rdbuf();
	std::smatch m;
	const std::string s = text.str();
	if (!std::regex_search(s, m, std::regex("\"scans\": *([0-9]+)")))
		throw std::runtime_error(summaryJson + ": no \"scans\" field");
	return std::stoul(m[1]);
}

std::string lineStartingWith(const std::string& file, const std::string& prefix)
{
	std::ifstream f(file);
	for (std::string line; std::getline(f, line);)
		if (line.rfind(prefix, 0) == 0) return line;
	return std::string(prefix.size(), ' ');
}

/** The number after `prefix` on the first line starting with it, 0 if none. */
size_t countAfter(const std::string& file, const std::string& prefix)
{
	const std::string line = lineStartingWith(file, prefix);
	return std::strtoul(line.c_str() + std::min(line.size(), prefix.size()), nullptr, 10);
}

TBackendRow measureBackend(const std::string& process, const TProcessConfig& config, const std::string& rawlog,
						   const std::string& truth, const std::string& outDir)
{
	TBackendRow row;
	row.name = rawlogName(rawlog);
	const std::string dir = outDir + "/" + row.name;
	fs::create_directories(dir);
	const auto run = [&](const std::string& tag, bool on) {
		const std::string out = dir + "/" + tag;
		fs::remove_all(out);
		// the bench's own settings after the user's overrides: the last one wins
		const std::string cmd = shellQuote(process) + config.arguments() + " -i " + shellQuote(rawlog) + " -o " +
								shellQuote(out) + " --set output.write_tiles=false --set loop_closure.enabled=" +
								(on ? "true" : "false");
		std::cerr << "\rgraph: " << row.name << " back-end " << tag << "   " << std::flush;
		const TChildTimes times = runTimedChild(cmd, dir + "/" + tag + ".log");
		std::optional<double> ate;
		if (!truth.empty()) ate = eval::evaluateTumFiles(truth, out + "/trajectory.tum").ate.position_m.rmse;
		return std::make_pair(times, ate);
	};
	std::tie(row.off, row.ate_off_m) = run("off", false);
	std::tie(row.on, row.ate_on_m) = run("on", true);
	std::cerr << "\n";
	row.scans = scansOf(dir + "/on/summary.json");
	row.closures = lineStartingWith(dir + "/on.log", "  closures tested:").substr(2);
	row.keyframes = countAfter(dir + "/on.log", "  keyframes:");  // the back-end works per keyframe
	return row;
}

std::string metresOrDash(const std::optional<double>& v)
{
	if (!v) return "-";
	std::ostringstream s;
	s << std::fixed << std::setprecision(3) << *v;
	return s.str();
}

void printBackendRows(const std::vector<TBackendRow>& rows)
{
	if (rows.empty()) return;
	std::cout << "\nThe back-end in hslam-process: whole-process CPU and wall ms per scan, loop closure off / on\n"
				 "(the back-end runs on its own thread: wall counts what a user waits; it works per keyframe,\n"
				 "the front-end per scan, so the ratio grows as scans per keyframe fall)\n";
	const CReportTable table(std::cout, {{"rawlog", 24, true},
										 {"scans", 7},
										 {"scans/kf", 9},
										 {"off ms", 10},
										 {"on ms", 10},
										 {"ratio", 8},
										 {"off wall", 10},
										 {"on wall", 10},
										 {"ratio", 8},
										 {"ATE off", 11},
										 {"ATE on", 11},
										 {"", 0, true}});
	table.printHeader();
	double extra = 0, off = 0, offWall = 0, onWall = 0, scans = 0;
	for (const auto& r : rows)
	{
		const double n = static_cast<double>(r.scans), offMs = 1000 * r.off.cpu_s / n, onMs = 1000 * r.on.cpu_s / n;
		const double offWallMs = 1000 * r.off.wall_s / n, onWallMs = 1000 * r.on.wall_s / n;
		const std::string perKeyframe = r.keyframes > 0 ? fixed(n / static_cast<double>(r.keyframes), 1) : "-";
		table.printRow({r.name.substr(0, 23), std::to_string(r.scans), perKeyframe, fixed(offMs, 2), fixed(onMs, 2),
						fixed(onMs / offMs, 2), fixed(offWallMs, 2), fixed(onWallMs, 2), fixed(onWallMs / offWallMs, 2),
						metresOrDash(r.ate_off_m), metresOrDash(r.ate_on_m), "   " + r.closures});
		extra += 1000 * (r.on.cpu_s - r.off.cpu_s), off += 1000 * r.off.cpu_s, scans += n;
		offWall += r.off.wall_s, onWall += r.on.wall_s;
	}
	CKeyValueLines keys(std::cout);
	for (const auto& r : rows)
	{
		keys("graph_" + r.name + "_cost_ratio", r.on.cpu_s / r.off.cpu_s);
		keys("graph_" + r.name + "_wall_ratio", r.on.wall_s / r.off.wall_s);
		if (r.keyframes > 0) keys("graph_" + r.name + "_scans_per_keyframe", static_cast<double>(r.scans) / r.keyframes);
		if (r.ate_on_m) keys("graph_" + r.name + "_ate_on_m", std::to_string(*r.ate_on_m));
	}
	keys("loop_closure_ms_per_scan", extra / scans)("loop_closure_cost_ratio", (off + extra) / off);
	keys("loop_closure_wall_ratio", onWall / offWall);
}
}  // namespace

int runGraphSuite(int argc, char** argv)
{
	TCLAP::CmdLine cmd("hslam-bench graph: pose-graph optimisation against graph size, and the loop-closure back-end's "
					   "cost in hslam-process", ' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> suite("suite", "graph", true, "", "suite", cmd);
	TCLAP::MultiArg<std::string> rawlogs("r", "rawlog", "rawlog(s) run with the back-end off and on (default: none)",
										 false, "file", cmd);
	TCLAP::MultiArg<std::string> truths("g", "ground-truth", "TUM ground truth of the i-th rawlog ('-' = none)", false,
										"file.tum", cmd);
	TCLAP::ValueArg<std::string> config("c", "config", "hslam-process INI (default config_ini/hslam-default.ini)", false,
										"config_ini/hslam-default.ini", "file.ini", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "folder for the runs (default ./hslam-bench-graph)", false,
									 "hslam-bench-graph", "dir", cmd);
	TCLAP::MultiArg<std::string> set("", "set", "SECTION.KEY=VALUE: override for every hslam-process run (repeatable)",
									 false, "SECTION.KEY=VALUE", cmd);
	TCLAP::ValueArg<int> maxKeyframes("", "max-keyframes", "largest synthetic graph (default 10000)", false, 10000, "N", cmd);
	if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);
	if (rawlogs.getValue().empty() && !set.getValue().empty())
		throw std::runtime_error("--set applies to the hslam-process runs: give them with -r RAWLOG");
	// checked before the synthetic graphs, so a typo fails at once
	const TProcessConfig processConfig = rawlogs.getValue().empty()
											 ? TProcessConfig{}
											 : TProcessConfig::checked(config.getValue(), set.getValue());
	const TLapRoute route;
	std::vector<TGraphSizeRow> ours, mrpt;
	for (int n : {500, 1000, 2000, 5000, 10000})
	{
		if (n > maxKeyframes.getValue()) break;
		std::cerr << "\rgraph: " << n << " keyframes   " << std::flush;
		ours.push_back(measureGraphSize(n, route, "sparse"));
		mrpt.push_back(measureGraphSize(n, route, "mrpt"));
	}
	std::cerr << "\n";
	printGraphRows(ours, mrpt);
	const std::string process = (fs::canonical("/proc/self/exe").parent_path() / "hslam-process").string();
	std::vector<TBackendRow> backend;
	for (size_t k = 0; k < rawlogs.getValue().size(); ++k)
	{
		std::string truth = k < truths.getValue().size() ? truths.getValue()[k] : "";
		if (truth == "-") truth.clear();
		backend.push_back(measureBackend(process, processConfig, rawlogs.getValue()[k], truth,
										 fs::absolute(out.getValue()).string()));
	}
	printBackendRows(backend);
	return 0;
}

}  // namespace hslam::bench
