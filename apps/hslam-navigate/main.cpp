/* hslam-navigate: drives a P3-DX to targets with the subsumption controller
 * of thesis 4.2 (libs/nav), recording as it goes.
 *
 *   hslam-navigate --sim config_ini/sim-nav-lab.ini --targets "1.5 2.7; 1.5 5.2" -o OUT
 *   hslam-navigate --thesis-trial 2 -o OUT          (figures 66-68, lab world)
 *   hslam-navigate --pioneer grabber.ini --laser-section LASER --targets-file T.txt -o OUT
 *
 * Writes into OUT: navigation.rawlog (every observation), path.csv, path.png
 * (path coloured by speed, obstacles, targets), live_map.png/.gridmap.gz (map
 * built while driving), config_used.ini; with --sim also ground_truth.tum and
 * gt_map.png. Exit 0 when every target was reached without collision, 3 when
 * not (outputs still written), 1 on errors. */
#include "CNavigationLog.h"
#include "pioneer_mode.h"
#include "sim_mode.h"

#include <hslam/common/version.h>
#include <hslam/common/command_line.h>
#include <hslam/common/parse_number.h>
#include <hslam/sim/nav_scenarios.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/poses/CPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace
{
using namespace hslam;
std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

std::vector<mrpt::math::TPoint2D> readTargetsFile(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error(path + ": cannot be opened");
	std::string line, all;
	for (int n = 1; std::getline(in, line); ++n)
	{
		const auto hash = line.find('#');
		line = common::trim(line.substr(0, hash));
		if (line.empty()) continue;
		nav::parseTargetList(line, path + ":" + std::to_string(n));  // errors name the line
		all += line + ";";
	}
	return nav::parseTargetList(all, path);
}

/** --start-pose "x y yaw_deg": the robot's world pose at its odometry origin
 * (the Pioneer zeroes its odometry at connection, reset_odometry). Targets
 * given in the world frame are moved into the odometry frame the controller
 * steers in (thesis 4.9: targets in the lab's frame). */
std::vector<mrpt::math::TPoint2D> targetsInOdometryFrame(const std::vector<mrpt::math::TPoint2D>& world,
														 const std::string& startText, const std::string& pioneerIni)
{
	if (pioneerIni.empty()) throw std::runtime_error("--start-pose is for --pioneer (the simulator knows its start)");
	std::istringstream is(startText);
	double x = 0, y = 0, yawDeg = 0;
	std::string rest;
	if (!(is >> x >> y >> yawDeg) || (is >> rest))
		throw std::runtime_error("--start-pose: expected 'x_m y_m yaw_deg', got '" + startText + "'");
	const mrpt::poses::CPose2D start(x, y, mrpt::DEG2RAD(yawDeg));
	std::vector<mrpt::math::TPoint2D> out;
	for (const auto& t : world)
	{
		const auto local = mrpt::poses::CPoint2D(t.x, t.y) - start;
		out.push_back({local.x(), local.y()});
	}
	return out;
}

double positive(const std::string& text, const std::string& what)
{
	const auto v = common::tryParseDouble(text);
	if (!v || *v <= 0) throw std::runtime_error(what + ": expected a positive number, got '" + text + "'");
	return *v;
}

/** Creates `out` (refusing one that holds a previous run) and writes the
 * controller options used into it. */
void prepareOutputFolder(const std::string& out, const nav::TSubsumptionOptions& navOptions)
{
	if (std::filesystem::exists(std::filesystem::path(out) / "navigation.rawlog"))
		throw std::runtime_error(out + ": holds a previous run (navigation.rawlog); choose another --out");
	std::filesystem::create_directories(out);
	mrpt::config::CConfigFileMemory used;
	navOptions.save(used);
	std::ofstream(std::filesystem::path(out) / "config_used.ini") << used.getContent();
}

struct TDriveOutcome
{
	bool ok = false;
	size_t reached = 0;
};

TDriveOutcome driveSimulatedRun(const std::string& simIni, const nav::TSubsumptionOptions& navOptions,
								const std::vector<mrpt::math::TPoint2D>& targets, double timeout_s,
								apps::CNavigationLog& log, const std::string& out)
{
	const auto r = apps::driveSimulated(simIni, navOptions, targets, timeout_s, log, out);
	std::cout << "simulated run: " << r.loop.time_s << " s, path " << r.loop.path_length_m << " m, min clearance "
			  << r.loop.min_clearance_m << " m, " << (r.loop.collided ? "COLLISION" : "no collision") << ", CPU "
			  << r.loop.cpuPerStep_us() << " us per control step\n";
	return {r.loop.success(), r.targets_reached};
}

TDriveOutcome drivePioneerRun(const apps::TPioneerDriveOptions& p, const nav::TSubsumptionOptions& navOptions,
							  const std::vector<mrpt::math::TPoint2D>& targets, apps::CNavigationLog& log)
{
	const auto r = apps::drivePioneer(p, navOptions, targets, log, g_stop);
	std::cout << "robot run: " << r.time_s << " s\n";
	return {r.finished, r.targets_reached};
}
}  // namespace

/** The command line (TCLAP arguments registered on `cmd`). */
struct TNavigateArgs
{
	explicit TNavigateArgs(TCLAP::CmdLine& c) : cmd(c) {}
	TCLAP::CmdLine& cmd;
	TCLAP::ValueArg<std::string> simArg{"", "sim", "Simulator INI (world, robot, sensors)", false, "", "SIM.ini", cmd};
	TCLAP::ValueArg<int> trialArg{"", "thesis-trial", "Thesis 4.2.2 trial 1, 2 or 3 (figures 66-68) in the lab world",
								  false, 0, "N", cmd};
	TCLAP::ValueArg<std::string> pioneerArg{"", "pioneer", "Grabber INI with the Pioneer (real robot or emulator)",
											false, "", "GRABBER.ini", cmd};
	TCLAP::ValueArg<std::string> pioneerSectionArg{"", "pioneer-section", "Its Pioneer section", false, "PIONEER",
												   "NAME", cmd};
	TCLAP::ValueArg<std::string> laserSectionArg{"", "laser-section", "Its laser section (empty: sonar only)", false,
												 "", "NAME", cmd};
	TCLAP::ValueArg<std::string> targetsArg{"", "targets", "Targets 'x y; x y; ...' (m, world frame)", false, "",
											"LIST", cmd};
	TCLAP::ValueArg<std::string> targetsFileArg{"", "targets-file", "Targets, one 'x y' per line", false, "", "FILE",
												cmd};
	TCLAP::ValueArg<std::string> startPoseArg{
		"", "start-pose",
		"With --pioneer: the robot's world pose 'x_m y_m yaw_deg' at its odometry origin; targets are then world "
		"coordinates (default: targets in the odometry frame)",
		false, "", "POSE", cmd};
	TCLAP::ValueArg<std::string> navArg{"c", "nav-config", "Controller INI (config_ini/nav-subsumption.ini)", false,
										"", "NAV.ini", cmd};
	TCLAP::ValueArg<std::string> outArg{"o", "out", "Output folder (created; must not hold a previous run)", false,
										"hslam-navigate-out", "DIR", cmd};
	TCLAP::ValueArg<std::string> timeoutArg{"", "timeout-s", "Give up after this time (s)", false, "300", "S", cmd};
};

/** The targets given on the command line; sets `simIni` (the thesis trials
 * drive in the lab world unless --sim says otherwise). */
std::vector<mrpt::math::TPoint2D> targetsOf(TNavigateArgs& args, std::string& simIni)
{
	std::vector<mrpt::math::TPoint2D> targets;
	simIni = args.simArg.getValue();
	if (args.trialArg.isSet())
	{
		const auto trials = sim::thesisTrials("config_ini/sim-worlds");
		if (args.trialArg.getValue() < 1 || args.trialArg.getValue() > 3) throw std::runtime_error("--thesis-trial: 1, 2 or 3");
		targets = trials[args.trialArg.getValue() - 1].targets;
		if (simIni.empty()) simIni = "config_ini/sim-nav-lab.ini";
	}
	if (args.targetsArg.isSet()) targets = nav::parseTargetList(args.targetsArg.getValue(), "--targets");
	if (args.targetsFileArg.isSet()) targets = readTargetsFile(args.targetsFileArg.getValue());
	if (targets.empty()) throw std::runtime_error("no target: give --targets, --targets-file or --thesis-trial");
	if (simIni.empty() == args.pioneerArg.getValue().empty())
		throw std::runtime_error("choose one robot: --sim INI (or --thesis-trial) or --pioneer INI");
	if (args.startPoseArg.isSet()) targets = targetsInOdometryFrame(targets, args.startPoseArg.getValue(), args.pioneerArg.getValue());
	return targets;
}

int main(int argc, char** argv)
{
	try
	{
		TCLAP::CmdLine cmd("Drives the P3-DX (simulated or real) to targets with the subsumption controller of "
						   "thesis 4.2, recording a rawlog, the live map, the path (CSV, PNG).",
						   ' ', hslam::common::versionText());
		TNavigateArgs args(cmd);
		if (!cmd.parse(argc, argv)) return common::exitCodeAfterParseStop(argc, argv);

		nav::TSubsumptionOptions navOptions;
		if (args.navArg.isSet()) navOptions = nav::TSubsumptionOptions::load(mrpt::config::CConfigFile(args.navArg.getValue()));
		std::string simIni;
		const auto targets = targetsOf(args, simIni);
		const double timeout_s = positive(args.timeoutArg.getValue(), "--timeout-s");

		const std::string out = args.outArg.getValue();
		prepareOutputFolder(out, navOptions);

		std::signal(SIGINT, onSignal);
		std::signal(SIGTERM, onSignal);
		apps::CNavigationLog log(out);
		const TDriveOutcome drive =
			simIni.empty()
				? drivePioneerRun({args.pioneerArg.getValue(), args.pioneerSectionArg.getValue(), args.laserSectionArg.getValue(), 0.1,
								   timeout_s},
								  navOptions, targets, log)
				: driveSimulatedRun(simIni, navOptions, targets, timeout_s, log, out);
		const bool ok = drive.ok;
		const size_t reached = drive.reached;
		log.finish();
		if (simIni.empty())
			log.renderPath(log.liveMap(), targets).saveToFile((std::filesystem::path(out) / "path.png").string());
		std::cout << "targets reached: " << reached << " / " << targets.size() << "\n"
				  << "outputs in " << out << " (navigation.rawlog, path.csv, path.png, live_map.png)\n";
		return ok ? 0 : 3;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-navigate: error: " << e.what() << "\n";
		return 1;
	}
}
