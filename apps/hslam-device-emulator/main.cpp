/* hslam-device-emulator: a Pioneer P3-DX (ARCOS, on a pseudo-terminal and/or a
 * loopback TCP port) and a SICK LMS200 (serial telegrams on a pseudo-terminal)
 * sharing one world, so MRPT's rawlog-grabber (with our plug-in) or
 * hslam-grabber can record without hardware. The robot moves as the client
 * commands (differential drive; with --sim-ini the simulator's P3-DX
 * kinematics with UMBmark odometry errors, thesis 4.1); sonars and laser see
 * the world: a simulator scene (libs/sim, --scene) or a rectangular room (--box);
 * with --scene and --sim-ini the simulator's sonar model (specular echoes,
 * multipath) and laser noise too.
 * Runs until SIGINT/SIGTERM or --duration; --truth writes the true pose (TUM). */
#include <hslam/common/command_line.h>
#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/common/version.h>
#include <hslam/hwdrivers/CArcosEmulator.h>
#include <hslam/hwdrivers/CLms200Emulator.h>
#include <hslam/sim/CDiffDriveRobot.h>
#include <hslam/sim/CLaserSimulator.h>
#include <hslam/sim/CSonarSimulator.h>
#include <hslam/sim/scene.h>
#include <hslam/common/ini_file.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/datetime.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <sstream>
#include <thread>

using namespace hslam::hwdrivers;

namespace
{
std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

/** The simulator's world (exact ray casting of walls, furniture, raster) as an
 * emulator world. People are not animated here (static scene). */
class CSimWorldAdapter : public CEmulatorWorld
{
   public:
	explicit CSimWorldAdapter(hslam::sim::CWorld world) : m_world(std::move(world)) {}
	double rayRange_m(double x, double y, double a, double maxRange_m) const override
	{
		const auto hit = m_world.castRay({x, y}, a, maxRange_m, false);
		return hit.hit ? hit.range_m : maxRange_m;
	}

   private:
	hslam::sim::CWorld m_world;
};

/** The simulator's P3-DX kinematics (UMBmark systematic + random odometry
 * errors, thesis 4.1) as the emulator's motion model. */
class CSimKinematics : public CEmulatorKinematics
{
   public:
	CSimKinematics(const hslam::sim::TDiffDriveOptions& o, const mrpt::poses::CPose2D& start, unsigned seed)
		: m_robot(o, start.asTPose()), m_rng(seed)
	{
	}
	void step(double v, double w, double dt) override { m_robot.step(v, w, dt, m_rng); }
	mrpt::poses::CPose2D truePose() const override { return mrpt::poses::CPose2D(m_robot.truePose()); }
	mrpt::poses::CPose2D odometryPose() const override { return mrpt::poses::CPose2D(m_robot.odometryPose()); }

   private:
	hslam::sim::CDiffDriveRobot m_robot;
	std::mt19937_64 m_rng;
};

/** The simulator's sonar model (cone sampling, specular reflection beyond
 * max_incidence, multipath, noise; thesis 4.3/4.6) on the emulator's sonars. */
CArcosEmulator::TSonarModel simSonarModel(std::shared_ptr<const hslam::sim::CWorld> world,
										  const hslam::sim::TSonarOptions& opts, unsigned seed)
{
	auto sonar = std::make_shared<hslam::sim::CSonarSimulator>(opts);
	auto rng = std::make_shared<std::mt19937_64>(seed);
	return [world, sonar, rng](const mrpt::poses::CPose2D& pose) {
		mrpt::obs::CObservationRange obs;
		sonar->simulate(*world, pose.asTPose(), *rng, obs);
		std::vector<double> r(sonar->ring().size(), sonar->options().max_range_m);
		for (const auto& m : obs.sensedData)
			if (m.sensorID < r.size()) r[m.sensorID] = m.sensedDistance > 0 ? m.sensedDistance : sonar->options().max_range_m;
		return r;
	};
}

/** The simulator's laser model (exact rays, Gaussian noise) at whatever field
 * of view and resolution the LMS200 client configured. */
CLms200Emulator::TScanModel simLaserModel(std::shared_ptr<const hslam::sim::CWorld> world, double noise_std_m, unsigned seed)
{
	auto rng = std::make_shared<std::mt19937_64>(seed);
	return [world, noise_std_m, rng](const mrpt::poses::CPose2D& laserPose, double fov, int n, double maxRange) {
		hslam::sim::TLaserOptions lo;
		lo.preset = "custom";
		lo.fov_rad = fov;
		lo.resolution_rad = fov / std::max(1, n - 1);
		lo.max_range_m = maxRange;
		lo.noise_std_m = noise_std_m;
		lo.range_resolution_m = 0;  // the LMS emulator quantises to its cm/mm units
		lo.x_m = lo.y_m = lo.yaw_rad = 0;  // laserPose is already the sensor's pose
		const hslam::sim::CLaserSimulator laser(lo);
		mrpt::obs::CObservation2DRangeScan scan;
		laser.simulate(*world, laserPose.asTPose(), *rng, scan);
		std::vector<double> r(static_cast<size_t>(n), maxRange);
		for (size_t i = 0; i < r.size() && i < scan.getScanSize(); ++i)
			r[i] = scan.getScanRangeValidity(i) ? scan.getScanRange(i) : maxRange;
		return r;
	};
}

std::vector<double> numbers(const std::string& text, size_t n, const std::string& what)
{
	std::istringstream is(text);
	std::vector<double> v(n);
	for (auto& x : v)
		if (!(is >> x)) throw std::runtime_error(what + " = '" + text + "': expected " + std::to_string(n) + " numbers");
	return v;
}
/** The command line. */
struct TEmulatorArgs
{
	std::string scene, box, sim_ini, start, pioneer_pty, lms200_pty, truth;
	int pioneer_tcp_port = -1;
	double lms200_rate_hz = 10, sip_period_s = 0.1;
	double bad_checksum_rate = 0, partial_rate = 0, garbage_rate = 0;
	double drop_every_s = 0, silence_every_s = 0, silence_for_s = 2, duration_s = 0;
};

/** Parses argv into `a`; false if --help or --version was printed. */
bool parseArgs(int argc, char** argv, TEmulatorArgs& a)
{
	TCLAP::CmdLine cmd("hslam-device-emulator: Pioneer ARCOS + SICK LMS200 emulators on pseudo-terminals/TCP", ' ', hslam::common::versionText());
	TCLAP::ValueArg<std::string> scene("", "scene", "simulator scene file (config_ini/sim-worlds/*.scene) (default: none)", false, "", "file", cmd);
	TCLAP::ValueArg<std::string> box("", "box", "rectangular room 'xmin ymin xmax ymax' (m) if no --scene (default: -2 -3 6 3)", false, "-2 -3 6 3", "text", cmd);
	TCLAP::ValueArg<std::string> simIni("", "sim-ini", "simulator INI (config_ini/sim-*.ini): [robot] kinematics with UMBmark errors drive the robot; with --scene also the [sonar] model (cone, specular, multipath, noise) and [laser] noise. Default: error-free kinematics, one exact ray per sonar/beam (default: none)", false, "", "file", cmd);
	TCLAP::ValueArg<std::string> start("", "start", "true start pose 'x_m y_m yaw_deg' (default: 0 0 0)", false, "0 0 0", "text", cmd);
	TCLAP::ValueArg<std::string> pioneerPty("", "pioneer-pty", "symlink for the Pioneer's pseudo-terminal ('' = none) (default: none)", false, "", "path", cmd);
	TCLAP::ValueArg<int> pioneerTcp("", "pioneer-tcp", "loopback TCP port for the Pioneer (-1 = none, 0 = any) (default: -1)", false, -1, "port", cmd);
	TCLAP::ValueArg<std::string> lmsPty("", "lms200-pty", "symlink for the LMS200's pseudo-terminal ('' = none) (default: none)", false, "", "path", cmd);
	TCLAP::ValueArg<double> lmsRate("", "lms200-rate", "laser scans per second (default: 10.0)", false, 10.0, "Hz", cmd);
	TCLAP::ValueArg<double> sipPeriod("", "sip-period", "SIP period (s), ARCOS default 0.1", false, 0.1, "s", cmd);
	TCLAP::ValueArg<double> badCk("", "bad-checksum-rate", "fraction of SIPs sent with a bad checksum (default: 0)", false, 0, "0..1", cmd);
	TCLAP::ValueArg<double> partial("", "partial-rate", "fraction of SIPs truncated (default: 0)", false, 0, "0..1", cmd);
	TCLAP::ValueArg<double> garbage("", "garbage-rate", "fraction of SIPs preceded by garbage bytes (default: 0)", false, 0, "0..1", cmd);
	TCLAP::ValueArg<double> dropEvery("", "drop-every", "pull the cable every N s: close TCP clients, re-create the pty (0 = never) (default: 0)", false, 0, "s", cmd);
	TCLAP::ValueArg<double> silenceEvery("", "silence-every", "go silent every N s (0 = never) (default: 0)", false, 0, "s", cmd);
	TCLAP::ValueArg<double> silenceFor("", "silence-for", "length of each silence (s) (default: 2.0)", false, 2.0, "s", cmd);
	TCLAP::ValueArg<double> duration("", "duration", "stop after this many seconds (0 = on SIGINT/SIGTERM) (default: 0)", false, 0, "s", cmd);
	TCLAP::ValueArg<std::string> truth("", "truth", "write the true robot pose at 20 Hz to this TUM file at exit (default: none)", false, "", "file", cmd);
	if (!cmd.parse(argc, argv)) return false;
	for (auto* arg : {&dropEvery, &silenceEvery, &duration})
		if (!(arg->getValue() >= 0)) throw std::runtime_error("--" + arg->getName() + ": expected a number of seconds >= 0");
	if (!(silenceFor.getValue() > 0)) throw std::runtime_error("--silence-for: expected a number of seconds > 0");
	a = {scene.getValue(), box.getValue(), simIni.getValue(), start.getValue(), pioneerPty.getValue(),
		 lmsPty.getValue(), truth.getValue(), pioneerTcp.getValue(), lmsRate.getValue(), sipPeriod.getValue(),
		 badCk.getValue(), partial.getValue(), garbage.getValue(), dropEvery.getValue(), silenceEvery.getValue(),
		 silenceFor.getValue(), duration.getValue()};
	return true;
}

/** The emulators' world, and the simulator's world behind it with --scene (else null). */
struct TEmulatedWorld
{
	std::shared_ptr<CEmulatorWorld> world;
	std::shared_ptr<const hslam::sim::CWorld> sim_world;
};

TEmulatedWorld makeWorld(const TEmulatorArgs& a)
{
	TEmulatedWorld w;
	if (!a.scene.empty())
	{
		w.sim_world = std::make_shared<hslam::sim::CWorld>(hslam::sim::loadSceneFile(a.scene).world);
		w.world = std::make_shared<CSimWorldAdapter>(*w.sim_world);
		return w;
	}
	const auto b = numbers(a.box, 4, "--box");
	w.world = std::make_shared<CBoxWorld>(CBoxWorld::TBox{b[0], b[1], b[2], b[3]});
	return w;
}

CArcosEmulator::TOptions pioneerOptions(const TEmulatorArgs& a)
{
	const auto s = numbers(a.start, 3, "--start");
	CArcosEmulator::TOptions eo;
	eo.use_pty = !a.pioneer_pty.empty();
	eo.pty_link = a.pioneer_pty;
	eo.tcp_port = a.pioneer_tcp_port;
	eo.sip_period_s = a.sip_period_s;
	eo.bad_checksum_rate = a.bad_checksum_rate;
	eo.partial_rate = a.partial_rate;
	eo.garbage_rate = a.garbage_rate;
	eo.start_pose = mrpt::poses::CPose2D(s[0], s[1], s[2] * M_PI / 180.0);
	return eo;
}

/** With --sim-ini: the simulator's kinematics, and with --scene its sonar and laser models. */
struct TSimModels
{
	std::shared_ptr<CEmulatorKinematics> kinematics;
	CArcosEmulator::TSonarModel sonar;
	CLms200Emulator::TScanModel laser;
};

TSimModels loadSimModels(const std::string& simIni, const mrpt::poses::CPose2D& startPose,
						 const std::shared_ptr<const hslam::sim::CWorld>& simWorld)
{
	TSimModels m;
	if (simIni.empty()) return m;
	const auto simCfg = hslam::common::loadIniFile(simIni);
	// Only the model sections are read here; their other keys (start
	// pose, rates, labels) belong to hslam-simulate.
	hslam::sim::TDiffDriveOptions ro;
	hslam::common::CSectionReader robotReader(simCfg, "robot");
	ro.visit(robotReader);
	m.kinematics = std::make_shared<CSimKinematics>(ro, startPose, 1);
	if (!simWorld) return m;
	hslam::sim::TSonarOptions so;
	hslam::common::CSectionReader sonarReader(simCfg, "sonar");
	so.visit(sonarReader);
	m.sonar = simSonarModel(simWorld, so, 2);
	hslam::sim::TLaserOptions lo;
	hslam::common::CSectionReader laserReader(simCfg, "laser");
	lo.visit(laserReader);
	m.laser = simLaserModel(simWorld, lo.noise_std_m, 3);
	return m;
}

/** The LMS200 emulator on --lms200-pty (null without), seeing what the Pioneer's true pose sees. */
std::unique_ptr<CLms200Emulator> startLms200(const TEmulatorArgs& a, const std::shared_ptr<CEmulatorWorld>& world,
											 const CLms200Emulator::TScanModel& scanModel, CArcosEmulator& pioneer)
{
	if (a.lms200_pty.empty()) return nullptr;
	CLms200Emulator::TOptions lo;
	lo.pty_link = a.lms200_pty;
	lo.scan_rate_hz = a.lms200_rate_hz;
	auto lms = std::make_unique<CLms200Emulator>(lo, world, [&pioneer] { return pioneer.truePose(); });
	if (scanModel) lms->setScanModel(scanModel);
	lms->start();
	return lms;
}

void printReady(const CArcosEmulator::TOptions& eo, const CArcosEmulator& pioneer, const CLms200Emulator* lms)
{
	std::cout << "ready";
	if (eo.use_pty) std::cout << " pioneer_pty=" << pioneer.ptyPath();
	if (eo.tcp_port >= 0) std::cout << " pioneer_tcp=" << pioneer.tcpPort();
	if (lms) std::cout << " lms200_pty=" << lms->ptyPath();
	std::cout << std::endl;
}

std::chrono::steady_clock::duration seconds(double s)
{
	return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s));
}

/** Runs until a signal or --duration, injecting the --drop-every / --silence-every
 * faults; returns the true pose every 50 ms when --truth is set. */
hslam::common::TTrajectory2D runUntilStop(const TEmulatorArgs& a, CArcosEmulator& pioneer)
{
	hslam::common::TTrajectory2D traj;
	const auto t0 = std::chrono::steady_clock::now();
	auto nextDrop = t0 + seconds(a.drop_every_s);
	auto nextSilence = t0 + seconds(a.silence_every_s);
	while (!g_stop)
	{
		std::this_thread::sleep_for(std::chrono::milliseconds(50));
		const auto now = std::chrono::steady_clock::now();
		if (a.drop_every_s > 0 && now >= nextDrop)
		{
			pioneer.dropConnection();
			std::cout << "fault: connection dropped" << std::endl;
			nextDrop += seconds(a.drop_every_s);
		}
		if (a.silence_every_s > 0 && now >= nextSilence)
		{
			pioneer.silence(a.silence_for_s);
			std::cout << "fault: silent for " << a.silence_for_s << " s" << std::endl;
			nextSilence += seconds(a.silence_every_s);
		}
		if (!a.truth.empty()) traj.push_back({mrpt::Clock::toDouble(mrpt::Clock::now()), pioneer.truePose().asTPose()});
		if (a.duration_s > 0 &&
			std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > a.duration_s)
			break;
	}
	return traj;
}

void printStats(const CArcosEmulator& pioneer, const CLms200Emulator* lms)
{
	const auto st = pioneer.stats();
	std::cout << "pioneer: sips=" << st.sipsSent << " commands=" << st.commands << " handshakes=" << st.handshakes
			  << " watchdog_stops=" << st.watchdogStops << " faults=" << st.faultsInjected << "\n";
	if (lms) std::cout << "lms200: scans=" << lms->scansSent() << " commands=" << lms->commandsReceived() << "\n";
}

int runEmulators(const TEmulatorArgs& a)
{
	const TEmulatedWorld w = makeWorld(a);
	const CArcosEmulator::TOptions eo = pioneerOptions(a);
	const TSimModels models = loadSimModels(a.sim_ini, eo.start_pose, w.sim_world);
	CArcosEmulator pioneer(eo, w.world, models.kinematics);
	if (models.sonar) pioneer.setSonarModel(models.sonar);
	pioneer.start();
	const auto lms = startLms200(a, w.world, models.laser, pioneer);
	std::signal(SIGINT, onSignal);
	std::signal(SIGTERM, onSignal);
	printReady(eo, pioneer, lms.get());
	const auto traj = runUntilStop(a, pioneer);
	if (lms) lms->stop();
	pioneer.stop();
	if (!a.truth.empty()) hslam::common::writeTumFile(a.truth, traj);
	printStats(pioneer, lms.get());
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TEmulatorArgs args;
		if (!parseArgs(argc, argv, args)) return hslam::common::exitCodeAfterParseStop(argc, argv);  // help, version or a parse error
		return runEmulators(args);
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-device-emulator: " << e.what() << "\n";
		return 1;
	}
}
