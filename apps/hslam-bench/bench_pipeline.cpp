/* hslam-bench pipeline: the whole default pipeline (the hslam-process
 * binary, config_ini/hslam-default.ini) against MRPT's icp-slam (stock
 * config_files/icp-slam/icp-slam_demo_classic.ini, windows and 3D output
 * off) on the same rawlogs, in paired runs on the same machine (issue 12).
 *
 *   hslam-bench pipeline [-r RAWLOG ...] [-g GROUND_TRUTH.tum ...] [-n N] [-c INI] [--out DIR]
 *
 * CPU time (user + system, from getrusage of the child processes) of each
 * whole process; start-up is excluded for BOTH programs alike by also running
 * each on a 1-scan prefix of the rawlog (the entries up to the first scan)
 * and taking ms per scan = (CPU(full) - CPU(prefix)) / (scans - 1). What
 * remains is reading, matching, mapping and writing the outputs. Each figure
 * is the minimum of N runs (default 3), runs of the two programs alternate.
 * Wall time is measured the same way and printed beside it
 * (`pipeline_wall_ms_per_scan=`, `pipeline_wall_speedup_vs_icp_slam=`): our
 * loop-closure back-end runs on a thread of its own, so on a machine with a
 * free core our wall time is below our CPU time; icp-slam's two are equal.
 * With a ground truth (-g, paired with -r by order; else ground_truth.tum or
 * <stem>.tum beside the rawlog) the ATE RMSE of both is printed, and of raw
 * odometry (hslam-process with pose_estimation.method = odometry, not timed).
 * Our loop-closure keyframes (summary.json) and CPU ms per keyframe are
 * printed too (`pipeline_<log>_pipeline_ms_per_keyframe=`): a log with a
 * scan every 1-3 s makes every scan a keyframe, a 10 Hz one every 4th-13th.
 * icp-slam's path (log_estimated_path.txt, one pose per rawlog step) is
 * mapped to the scans' timestamps by reading the rawlog step by step with
 * the same MRPT call icp-slam uses. Runs and trajectories stay in --out. */
#include "bench_common.h"
#include "bench_report.h"
#include "child_process.h"

#include <hslam/common/command_line.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <regex>
#include <sstream>

namespace hslam::bench
{
namespace
{
namespace fs = std::filesystem;
const char* kIcpSlamStockIni = "/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini";

/** One rawlog as both programs see it. */
struct TBenchRawlog
{
	std::string name, path, ground_truth;  //!< ground_truth empty = none
	size_t scans = 0;
	std::vector<std::optional<double>> step_scan_time_s;  //!< per icp-slam step: the scan's time, if it has one
};

/** CPU and wall seconds (each the best of the repetitions) of the full run
 * and of the prefix run. CPU counts every thread; wall is what a user waits
 * (less than CPU when the loop-closure back-end runs on its own thread). */
struct TProgramTimes
{
	double full_s = 1e300, prefix_s = 1e300;
	double full_wall_s = 1e300, prefix_wall_s = 1e300;
	double msPerScan(size_t scans) const { return 1000.0 * (full_s - prefix_s) / static_cast<double>(scans - 1); }
	double wallMsPerScan(size_t scans) const
	{
		return 1000.0 * (full_wall_s - prefix_wall_s) / static_cast<double>(scans - 1);
	}
	void keepBest(const TChildTimes& full, const TChildTimes& prefix)
	{
		full_s = std::min(full_s, full.cpu_s), full_wall_s = std::min(full_wall_s, full.wall_s);
		prefix_s = std::min(prefix_s, prefix.cpu_s), prefix_wall_s = std::min(prefix_wall_s, prefix.wall_s);
	}
};

struct TBenchRow
{
	TBenchRawlog log;
	TProgramTimes ours, icp;
	std::optional<double> ate_odometry_m, ate_ours_m, ate_icp_m;
	std::string icp_note;
	std::optional<size_t> keyframes;  //!< our loop-closure keyframes (summary.json), if the back-end ran
	/** Our CPU ms per keyframe (start-up excluded): each keyframe runs ICP and
	 * a loop-closure search, so a log with a scan every 1-3 s, where every
	 * scan is a keyframe, costs per scan what a 10 Hz log costs per keyframe. */
	std::optional<double> oursMsPerKeyframe() const
	{
		if (!keyframes || *keyframes == 0) return std::nullopt;
		return 1000.0 * (ours.full_s - ours.prefix_s) / static_cast<double>(*keyframes);
	}
};

/** The loop-closure keyframes in an hslam-process summary.json, if any. */
std::optional<size_t> keyframesIn(const std::string& summaryJson)
{
	std::ifstream in(summaryJson);
	std::stringstream text;
	text << in.rdbuf();
	static const std::regex kKeyframes("\"keyframes\": *([0-9]+)");
	std::smatch m;
	const std::string s = text.str();
	if (!std::regex_search(s, m, kKeyframes)) return std::nullopt;
	return static_cast<size_t>(std::stoul(m[1].str()));
}

std::string findGroundTruth(const std::string& rawlog)
{
	const fs::path p(rawlog);
	for (const fs::path& c : {p.parent_path() / "ground_truth.tum", fs::path(p).replace_extension(".tum")})
		if (fs::exists(c)) return c.string();
	return "";
}

std::optional<double> scanTimeOf(const mrpt::obs::CSensoryFrame::Ptr& frame, const mrpt::obs::CObservation::Ptr& obs)
{
	using mrpt::obs::CObservation2DRangeScan;
	if (obs && IS_CLASS(*obs, CObservation2DRangeScan)) return mrpt::Clock::toDouble(obs->timestamp);
	if (frame)
		if (const auto scan = frame->getObservationByClass<CObservation2DRangeScan>(); scan)
			return mrpt::Clock::toDouble(scan->timestamp);
	return std::nullopt;
}

/** Reads the rawlog step by step as icp-slam does (same MRPT call), notes the
 * scan time of every step and writes the entries up to the first scan to `prefixPath`. */
void readSteps(TBenchRawlog& log, const std::string& prefixPath)
{
	mrpt::io::CFileGZInputStream in;
	if (!in.open(log.path)) throw std::runtime_error(log.path + ": cannot open");
	auto arch = mrpt::serialization::archiveFrom(in);
	mrpt::io::CFileGZOutputStream prefixFile(prefixPath);
	auto prefix = mrpt::serialization::archiveFrom(prefixFile);
	mrpt::obs::CActionCollection::Ptr actions;
	mrpt::obs::CSensoryFrame::Ptr frame;
	mrpt::obs::CObservation::Ptr obs;
	size_t entry = 0;
	while (mrpt::obs::CRawlog::getActionObservationPairOrObservation(arch, actions, frame, obs, entry))
	{
		const auto t = scanTimeOf(frame, obs);
		if (log.scans == 0)
		{
			if (obs) prefix << *obs;
			else prefix << *actions << *frame;
		}
		log.step_scan_time_s.push_back(t);
		if (t) ++log.scans;
	}
	if (log.scans < 2) throw std::runtime_error(log.path + ": fewer than 2 laser scans");
}

std::string writeIcpSlamIni(const std::string& rawlog, const std::string& logDir, const std::string& iniPath)
{
	if (!fs::exists(kIcpSlamStockIni))
		throw std::runtime_error(std::string(kIcpSlamStockIni) + " not found (Debian package mrpt-common)");
	std::ifstream stock(kIcpSlamStockIni);
	std::stringstream text;
	text << stock.rdbuf();
	mrpt::config::CConfigFileMemory cfg(text.str());
	// I/O only; every algorithm parameter stays stock. LOG_FREQUENCY = 0:
	// icp-slam would otherwise build (and, with SAVE_3D_SCENE off, discard) a
	// 3D scene every 50 steps, work that is not SLAM.
	const std::vector<std::pair<std::string, std::string>> io = {
		{"rawlog_file", rawlog}, {"logOutput_dir", logDir}, {"SHOW_PROGRESS_3D_REAL_TIME", "0"},
		{"SAVE_3D_SCENE", "0"}, {"SAVE_POSE_LOG", "0"}, {"LOG_FREQUENCY", "0"}};
	for (const auto& [key, value] : io) cfg.write("MappingApplication", key, value);
	std::ofstream(iniPath) << cfg.getContent();
	return iniPath;
}

/** icp-slam's "step x y yaw" rows at the steps that hold a scan, as TUM rows. */
common::TTrajectory2D icpSlamTrajectory(const std::string& pathFile, const TBenchRawlog& log)
{
	std::ifstream f(pathFile);
	if (!f) throw std::runtime_error(pathFile + ": missing (icp-slam wrote no path)");
	common::TTrajectory2D out;
	for (std::string line; std::getline(f, line);)
	{
		std::istringstream row(line);
		long step = -1;
		mrpt::math::TPose2D p;
		if (!(row >> step >> p.x >> p.y >> p.phi)) continue;
		if (step >= 0 && static_cast<size_t>(step) < log.step_scan_time_s.size() && log.step_scan_time_s[step])
			out.push_back({*log.step_scan_time_s[step], p});
	}
	return out;
}

/** Paths of one benchmark run. */
struct TBenchSetup
{
	std::string hslam_process, out_dir;
	TProcessConfig config;
	int repetitions = 3;
};

std::string processCommand(const TBenchSetup& setup, const std::string& rawlog, const std::string& outDir,
						   const std::string& extra = "")
{
	return shellQuote(setup.hslam_process) + " -q" + setup.config.arguments() + " -i " + shellQuote(rawlog) + " -o " +
		   shellQuote(outDir) + extra;
}

std::optional<double> ateOf(const std::string& groundTruth, const std::string& trajectory)
{
	if (groundTruth.empty()) return std::nullopt;
	return eval::evaluateTumFiles(groundTruth, trajectory).ate.position_m.rmse;
}

/** Times both programs on one rawlog (and its 1-scan prefix), then scores them. */
TBenchRow benchOneRawlog(const TBenchSetup& setup, TBenchRawlog log)
{
	const std::string dir = setup.out_dir + "/" + log.name;
	fs::create_directories(dir);
	const std::string prefix = dir + "/first-scan.rawlog";
	readSteps(log, prefix);
	TBenchRow row;
	const std::string icpFull = writeIcpSlamIni(fs::absolute(log.path).string(), dir + "/icp-slam", dir + "/icp-slam.ini");
	const std::string icpPrefix = writeIcpSlamIni(prefix, dir + "/icp-slam-prefix", dir + "/icp-slam-prefix.ini");
	for (int r = 0; r < setup.repetitions; ++r)
	{
		std::cerr << "\r" << log.name << ": run " << r + 1 << "/" << setup.repetitions << std::flush;
		const auto oursFull = runTimedChild(processCommand(setup, log.path, dir + "/hslam"), dir + "/hslam.log");
		const auto icpFullRun = runTimedChild("icp-slam " + shellQuote(icpFull), dir + "/icp-slam.log");
		const auto oursPrefix = runTimedChild(processCommand(setup, prefix, dir + "/hslam-prefix"), dir + "/hslam-prefix.log");
		const auto icpPrefixRun = runTimedChild("icp-slam " + shellQuote(icpPrefix), dir + "/icp-slam-prefix.log");
		row.ours.keepBest(oursFull, oursPrefix);
		row.icp.keepBest(icpFullRun, icpPrefixRun);
	}
	std::cerr << "\n";
	row.keyframes = keyframesIn(dir + "/hslam/summary.json");
	if (!log.ground_truth.empty())
	{
		childCpuSeconds(processCommand(setup, log.path, dir + "/odometry", " --set pose_estimation.method=odometry"),
						dir + "/odometry.log");
		row.ate_odometry_m = ateOf(log.ground_truth, dir + "/odometry/trajectory.tum");
		row.ate_ours_m = ateOf(log.ground_truth, dir + "/hslam/trajectory.tum");
		const auto icpPath = icpSlamTrajectory(dir + "/icp-slam/log_estimated_path.txt", log);
		common::writeTumFile(dir + "/icp-slam.tum", icpPath);
		try
		{
			row.ate_icp_m = ateOf(log.ground_truth, dir + "/icp-slam.tum");
		}
		catch (const std::exception& e)
		{
			row.icp_note = e.what();
		}
	}
	row.log = std::move(log);
	return row;
}

std::string fixedOrDash(const std::optional<double>& v, int digits)
{
	if (!v) return "-";
	std::ostringstream s;
	s << std::fixed << std::setprecision(digits) << *v;
	return s.str();
}

void printTable(const std::vector<TBenchRow>& rows)
{
	std::cout << "\nWhole-process CPU ms per scan (start-up excluded: minus a 1-scan run), wall ms per scan the same "
				 "way, ATE RMSE (m); keyframes of our loop-closure back-end and our CPU ms per keyframe\n";
	const CReportTable table(std::cout, {{"rawlog", 26, true},
										 {"scans", 7},
										 {"keyfr", 7},
										 {"ours ms", 10},
										 {"icp ms", 10},
										 {"speedup", 9},
										 {"ours wall", 10},
										 {"icp wall", 10},
										 {"ATE odo", 10},
										 {"ATE ours", 10},
										 {"ATE icp", 10},
										 {"ours/kf", 9},
										 {"", 0, true}});
	table.printHeader();
	for (const auto& r : rows)
	{
		const double ours = r.ours.msPerScan(r.log.scans), icp = r.icp.msPerScan(r.log.scans);
		const std::optional<double> keyframes =
			r.keyframes ? std::optional<double>(static_cast<double>(*r.keyframes)) : std::nullopt;
		table.printRow({r.log.name.substr(0, 25), std::to_string(r.log.scans), fixedOrDash(keyframes, 0),
						fixedOrDash(ours, 3), fixedOrDash(icp, 3),
						fixedOrDash(icp / ours, 2), fixedOrDash(r.ours.wallMsPerScan(r.log.scans), 3),
						fixedOrDash(r.icp.wallMsPerScan(r.log.scans), 3), fixedOrDash(r.ate_odometry_m, 3),
						fixedOrDash(r.ate_ours_m, 3),
						fixedOrDash(r.ate_icp_m, 3), fixedOrDash(r.oursMsPerKeyframe(), 2),
						r.icp_note.empty() ? "" : "  icp-slam: " + r.icp_note});
	}
}

void printKeyValues(const std::vector<TBenchRow>& rows)
{
	double oursMs = 0, icpMs = 0, oursWallMs = 0, icpWallMs = 0, intervals = 0;
	std::cout << "\n";
	CKeyValueLines keys(std::cout);
	for (const auto& r : rows)
	{
		const double ours = r.ours.msPerScan(r.log.scans), icp = r.icp.msPerScan(r.log.scans);
		const double oursWall = r.ours.wallMsPerScan(r.log.scans), icpWall = r.icp.wallMsPerScan(r.log.scans);
		const std::string k = "pipeline_" + r.log.name + "_";
		keys(k + "pipeline_ms_per_scan", ours)(k + "icp_slam_ms_per_scan", icp)(k + "pipeline_speedup_vs_icp_slam",
																			   icp / ours);
		keys(k + "pipeline_wall_ms_per_scan", oursWall)(k + "icp_slam_wall_ms_per_scan", icpWall)(
			k + "pipeline_wall_speedup_vs_icp_slam", icpWall / oursWall);
		if (r.ate_ours_m) keys(k + "pipeline_ate_m", *r.ate_ours_m);
		if (r.ate_icp_m) keys(k + "icp_slam_ate_m", *r.ate_icp_m);
		if (r.ate_odometry_m) keys(k + "odometry_ate_m", *r.ate_odometry_m);
		if (const auto perKeyframe = r.oursMsPerKeyframe())
			keys(k + "keyframes", static_cast<double>(*r.keyframes))(k + "pipeline_ms_per_keyframe", *perKeyframe);
		const double n = static_cast<double>(r.log.scans - 1);
		oursMs += ours * n, icpMs += icp * n, intervals += n;
		oursWallMs += oursWall * n, icpWallMs += icpWall * n;
	}
	keys("pipeline_ms_per_scan", oursMs / intervals)("icp_slam_ms_per_scan", icpMs / intervals)(
		"pipeline_speedup_vs_icp_slam", icpMs / oursMs);
	keys("pipeline_wall_ms_per_scan", oursWallMs / intervals)("icp_slam_wall_ms_per_scan", icpWallMs / intervals)(
		"pipeline_wall_speedup_vs_icp_slam", icpWallMs / oursWallMs);
}

/** -r defaults: MRPT's sample rawlog and every rawlog_samples/<name>/sim.rawlog. */
std::vector<std::string> defaultRawlogs()
{
	std::vector<std::string> out{kMrptSampleRawlog}, samples;
	if (fs::is_directory("rawlog_samples"))
		for (const auto& d : fs::directory_iterator("rawlog_samples"))
			if (fs::exists(d.path() / "sim.rawlog")) samples.push_back((d.path() / "sim.rawlog").string());
	std::sort(samples.begin(), samples.end());
	out.insert(out.end(), samples.begin(), samples.end());
	return out;
}

std::vector<TBenchRawlog> describeRawlogs(const std::vector<std::string>& paths, const std::vector<std::string>& truths)
{
	std::vector<TBenchRawlog> out;
	for (size_t k = 0; k < paths.size(); ++k)
	{
		TBenchRawlog log;
		log.path = paths[k];
		if (!fs::exists(log.path)) throw std::runtime_error(log.path + ": rawlog not found");
		log.name = rawlogName(log.path);
		log.ground_truth = k < truths.size() ? truths[k] : findGroundTruth(log.path);
		if (log.ground_truth == "-") log.ground_truth.clear();
		if (!log.ground_truth.empty() && !fs::exists(log.ground_truth))
			throw std::runtime_error(log.ground_truth + ": ground truth not found (for " + log.path + ")");
		out.push_back(log);
	}
	return out;
}
}  // namespace

int runPipelineSuite(int argc, char** argv)
{
	TCLAP::CmdLine cmd("hslam-bench pipeline: default pipeline (hslam-process) vs MRPT icp-slam, CPU ms per scan and ATE",
					   ' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> suite("suite", "pipeline", true, "", "suite", cmd);
	TCLAP::MultiArg<std::string> rawlogs("r", "rawlog", "rawlog(s) (default: MRPT's sample and rawlog_samples/*/sim.rawlog)",
										 false, "file", cmd);
	TCLAP::MultiArg<std::string> truths("g", "ground-truth", "TUM ground truth of the i-th rawlog ('-' = none; default: "
										"ground_truth.tum or <stem>.tum beside the rawlog)", false, "file.tum", cmd);
	TCLAP::ValueArg<int> repetitions("n", "repetitions", "timed runs per program, best kept (default 3)", false, 3, "N", cmd);
	TCLAP::ValueArg<std::string> config("c", "config", "hslam-process INI (default config_ini/hslam-default.ini)", false,
										"config_ini/hslam-default.ini", "file.ini", cmd);
	TCLAP::MultiArg<std::string> set("", "set", "SECTION.KEY=VALUE: override for every hslam-process run (repeatable)",
									 false, "SECTION.KEY=VALUE", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "folder for the runs (default ./hslam-bench-pipeline)", false,
									 "hslam-bench-pipeline", "dir", cmd);
	if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);
	TBenchSetup setup;
	setup.hslam_process = (fs::canonical("/proc/self/exe").parent_path() / "hslam-process").string();
	setup.out_dir = fs::absolute(out.getValue()).string();
	setup.repetitions = std::max(1, repetitions.getValue());
	if (!fs::exists(setup.hslam_process)) throw std::runtime_error(setup.hslam_process + " not found");
	setup.config = TProcessConfig::checked(config.getValue(), set.getValue());
	if (std::system("command -v icp-slam >/dev/null 2>&1") != 0)
		throw std::runtime_error("icp-slam not in PATH (Debian package mrpt-apps)");
	const auto logs = describeRawlogs(rawlogs.getValue().empty() ? defaultRawlogs() : rawlogs.getValue(), truths.getValue());
	std::cout << "Suite pipeline: " << logs.size() << " rawlog(s), " << setup.repetitions
			  << " paired run(s) each; runs in " << setup.out_dir << "\n";
	for (const auto& o : setup.config.overrides) std::cout << "  --set " << o << "\n";
	std::vector<TBenchRow> rows;
	int failed = 0;
	for (const auto& log : logs)
	{
		try
		{
			rows.push_back(benchOneRawlog(setup, log));
		}
		catch (const std::exception& e)  // keep the other rawlogs' figures
		{
			std::cerr << "\nhslam-bench pipeline: " << log.path << ": " << e.what() << "\n";
			++failed;
		}
	}
	if (!rows.empty())
	{
		printTable(rows);
		printKeyValues(rows);
	}
	return failed == 0 ? 0 : 1;
}

}  // namespace hslam::bench
