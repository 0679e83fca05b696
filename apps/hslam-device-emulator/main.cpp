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
}  // namespace

int main(int argc, char** argv)
{
	try
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
		if (!cmd.parse(argc, argv)) return 0;
		for (auto* a : {&dropEvery, &silenceEvery, &duration})
			if (!(a->getValue() >= 0)) throw std::runtime_error("--" + a->getName() + ": expected a number of seconds >= 0");
		if (!(silenceFor.getValue() > 0)) throw std::runtime_error("--silence-for: expected a number of seconds > 0");

		std::shared_ptr<CEmulatorWorld> world;
		std::shared_ptr<const hslam::sim::CWorld> simWorld;
		if (!scene.getValue().empty())
		{
			simWorld = std::make_shared<hslam::sim::CWorld>(hslam::sim::loadSceneFile(scene.getValue()).world);
			world = std::make_shared<CSimWorldAdapter>(*simWorld);
		}
		else
		{
			const auto b = numbers(box.getValue(), 4, "--box");
			world = std::make_shared<CBoxWorld>(CBoxWorld::TBox{b[0], b[1], b[2], b[3]});
		}
		const auto s = numbers(start.getValue(), 3, "--start");

		CArcosEmulator::TOptions eo;
		eo.use_pty = !pioneerPty.getValue().empty();
		eo.pty_link = pioneerPty.getValue();
		eo.tcp_port = pioneerTcp.getValue();
		eo.sip_period_s = sipPeriod.getValue();
		eo.bad_checksum_rate = badCk.getValue();
		eo.partial_rate = partial.getValue();
		eo.garbage_rate = garbage.getValue();
		eo.start_pose = mrpt::poses::CPose2D(s[0], s[1], s[2] * M_PI / 180.0);
		std::shared_ptr<CEmulatorKinematics> kinematics;
		CArcosEmulator::TSonarModel sonarModel;
		CLms200Emulator::TScanModel scanModel;
		if (!simIni.getValue().empty())
		{
			const auto simCfg = hslam::common::loadIniFile(simIni.getValue());
			// Only the model sections are read here; their other keys (start
			// pose, rates, labels) belong to hslam-simulate.
			hslam::sim::TDiffDriveOptions ro;
			hslam::common::CSectionReader robotReader(simCfg, "robot");
			ro.visit(robotReader);
			kinematics = std::make_shared<CSimKinematics>(ro, eo.start_pose, 1);
			if (simWorld)
			{
				hslam::sim::TSonarOptions so;
				hslam::common::CSectionReader sonarReader(simCfg, "sonar");
				so.visit(sonarReader);
				sonarModel = simSonarModel(simWorld, so, 2);
				hslam::sim::TLaserOptions lo;
				hslam::common::CSectionReader laserReader(simCfg, "laser");
				lo.visit(laserReader);
				scanModel = simLaserModel(simWorld, lo.noise_std_m, 3);
			}
		}
		CArcosEmulator pioneer(eo, world, kinematics);
		if (sonarModel) pioneer.setSonarModel(sonarModel);
		pioneer.start();

		std::unique_ptr<CLms200Emulator> lms;
		if (!lmsPty.getValue().empty())
		{
			CLms200Emulator::TOptions lo;
			lo.pty_link = lmsPty.getValue();
			lo.scan_rate_hz = lmsRate.getValue();
			lms = std::make_unique<CLms200Emulator>(lo, world, [&pioneer] { return pioneer.truePose(); });
			if (scanModel) lms->setScanModel(scanModel);
			lms->start();
		}
		std::signal(SIGINT, onSignal);
		std::signal(SIGTERM, onSignal);
		std::cout << "ready";
		if (eo.use_pty) std::cout << " pioneer_pty=" << pioneer.ptyPath();
		if (eo.tcp_port >= 0) std::cout << " pioneer_tcp=" << pioneer.tcpPort();
		if (lms) std::cout << " lms200_pty=" << lms->ptyPath();
		std::cout << std::endl;

		hslam::common::TTrajectory2D traj;
		const auto t0 = std::chrono::steady_clock::now();
		auto nextDrop = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(dropEvery.getValue()));
		auto nextSilence = t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(silenceEvery.getValue()));
		const auto every = [](double s) { return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(s)); };
		while (!g_stop)
		{
			std::this_thread::sleep_for(std::chrono::milliseconds(50));
			const auto now = std::chrono::steady_clock::now();
			if (dropEvery.getValue() > 0 && now >= nextDrop)
			{
				pioneer.dropConnection();
				std::cout << "fault: connection dropped" << std::endl;
				nextDrop += every(dropEvery.getValue());
			}
			if (silenceEvery.getValue() > 0 && now >= nextSilence)
			{
				pioneer.silence(silenceFor.getValue());
				std::cout << "fault: silent for " << silenceFor.getValue() << " s" << std::endl;
				nextSilence += every(silenceEvery.getValue());
			}
			if (!truth.getValue().empty())
				traj.push_back({mrpt::Clock::toDouble(mrpt::Clock::now()), pioneer.truePose().asTPose()});
			if (duration.getValue() > 0 &&
				std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > duration.getValue())
				break;
		}
		if (lms) lms->stop();
		pioneer.stop();
		if (!truth.getValue().empty()) hslam::common::writeTumFile(truth.getValue(), traj);
		const auto st = pioneer.stats();
		std::cout << "pioneer: sips=" << st.sipsSent << " commands=" << st.commands << " handshakes=" << st.handshakes
				  << " watchdog_stops=" << st.watchdogStops << " faults=" << st.faultsInjected << "\n";
		if (lms) std::cout << "lms200: scans=" << lms->scansSent() << " commands=" << lms->commandsReceived() << "\n";
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-device-emulator: " << e.what() << "\n";
		return 1;
	}
}
