/* Integration: the device emulators (hslam-device-emulator: Pioneer ARCOS and
 * SICK LMS200 on pseudo-terminals; a box room or the simulator's lab scene) recorded by MRPT's real
 * rawlog-grabber with our plug-in and by hslam-grabber, using the shipped
 * config_ini/grabber-pioneer-lms200.ini with the device paths replaced, while
 * a test client commands a motion over UDP (teleop_udp_port). The rawlog is
 * checked: odometry follows the commanded motion and ends at the true pose,
 * sonar and laser ranges equal the world's at the recorded poses, timestamps
 * increase, rawlog-edit --info reads it and hslam-process maps it. Stop
 * behaviour of hslam-grabber (SIGTERM, SIGKILL) is checked too. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/hwdrivers/CEmulatorWorld.h>
#include <hslam/hwdrivers/CPseudoTerminal.h>
#include <hslam/hwdrivers/CUdpVelocityReceiver.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/sim/scene.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/system/datetime.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include "background_process.h"

using namespace hslam::hwdrivers;
namespace fs = std::filesystem;

namespace
{
/** Where the emulated robot lives, and the expected range along a ray there. */
struct TWorldSetup
{
	std::vector<std::string> emulatorArgs;
	mrpt::poses::CPose2D start;
	std::function<double(double x, double y, double a, double maxRange)> ray;
};

/** A rectangular room (the emulator's own CBoxWorld). */
TWorldSetup boxRoom()
{
	auto world = std::make_shared<CBoxWorld>(CBoxWorld::TBox{-2, -3, 6, 3});
	return {{"--box", "-2 -3 6 3", "--start", "1 0.5 0"},
			mrpt::poses::CPose2D(1.0, 0.5, 0.0),
			[world](double x, double y, double a, double m) { return world->rayRange_m(x, y, a, m); }};
}

/** The simulator's lab scene (walls, furniture, chair legs), ranges from the
 * simulator's own ray caster. */
TWorldSetup labScene()
{
	const std::string scene = std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-worlds/lab.scene";
	auto world = std::make_shared<hslam::sim::CWorld>(hslam::sim::loadSceneFile(scene).world);
	return {{"--scene", scene, "--start", "1.5 1.5 0"},
			mrpt::poses::CPose2D(1.5, 1.5, 0.0),
			[world](double x, double y, double a, double m) {
				const auto h = world->castRay({x, y}, a, m, false);
				return h.hit ? h.range_m : m;
			}};
}

constexpr double V_CMD = 0.3, W_CMD = 0.25, MOTION_S = 2.5;

std::string readFile(const std::string& p)
{
	std::ifstream f(p);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

/** A UDP teleop port for test `k`: below Linux's ephemeral range
 * (32768-60999), where the sockets of tests running in parallel are given
 * their local ports and could hold it; per process, so that two runs of the
 * suite do not meet either. */
int teleopPort(int k) { return 21000 + 1500 * k + static_cast<int>(getpid() % 1500); }

/** The shipped INI with the emulator's devices and a UDP teleop port. */
std::string writeIni(const hslam::testing::CTempDir& tmp, int udpPort, bool sensoryFrames)
{
	mrpt::config::CConfigFileMemory cfg(readFile(std::string(HSLAM_SOURCE_DIR) + "/config_ini/grabber-pioneer-lms200.ini"));
	cfg.write("global", "rawlog_prefix", tmp.file("rec"));
	cfg.write("global", "GRABBER_PERIOD_MS", "200");
	cfg.write("global", "time_between_launches", "100");
	cfg.write("global", "use_sensoryframes", sensoryFrames ? "1" : "0");
	cfg.write("PIONEER", "COM_port_LIN", tmp.file("pioneer"));
	cfg.write("PIONEER", "teleop_udp_port", std::to_string(udpPort));
	cfg.write("LASER", "COM_port_LIN", tmp.file("lms"));
	cfg.write("LASER", "nTries_connect", "1");
	const std::string path = tmp.file("grab.ini");
	std::ofstream(path) << cfg.getContent();
	return path;
}

std::unique_ptr<CBackgroundProcess> startEmulators(const hslam::testing::CTempDir& tmp, const TWorldSetup& w)
{
	std::vector<std::string> args{std::string(HSLAM_BIN_DIR) + "/hslam-device-emulator", "--pioneer-pty", tmp.file("pioneer"),
								  "--lms200-pty", tmp.file("lms"), "--truth", tmp.file("truth.tum")};
	args.insert(args.end(), w.emulatorArgs.begin(), w.emulatorArgs.end());
	auto p = std::make_unique<CBackgroundProcess>(args, tmp.file("emulator.log"));
	EXPECT_TRUE(p->waitForLog("ready", 30.0)) << p->log();
	return p;
}

/** Test client: waits until the recorder's log shows the Pioneer link up,
 * then `delay_s`, commands (V_CMD, W_CMD) for MOTION_S, then zero; then
 * creates `doneMarker` (if given) so the recorder can be stopped on the
 * motion's end rather than after a fixed wall-clock time (issue 19). */
std::thread motionClient(int port, double delay_s, std::string recorderLog, std::string doneMarker = "")
{
	return std::thread([=] {
		const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
		while (readFile(recorderLog).find("link up") == std::string::npos && std::chrono::steady_clock::now() < deadline)
			std::this_thread::sleep_for(std::chrono::milliseconds(20));
		std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));
		const auto t0 = std::chrono::steady_clock::now();
		while (std::chrono::steady_clock::now() - t0 < std::chrono::duration<double>(MOTION_S))
		{
			sendUdpVelocity(port, V_CMD, W_CMD);
			std::this_thread::sleep_for(std::chrono::milliseconds(100));
		}
		for (int k = 0; k < 5; ++k)
		{
			sendUdpVelocity(port, 0, 0);
			std::this_thread::sleep_for(std::chrono::milliseconds(100));
		}
		if (!doneMarker.empty()) std::ofstream(doneMarker) << "done\n";
	});
}

/** Time the recorder keeps running after the motion, for the laser scans of
 * the robot standing still (at least 5 are checked, the LMS200 emulator
 * sends about 10 per second). */
constexpr double STILL_S = 3.0;

/** Runs hslam-grabber in the background until the motion client is done plus
 * STILL_S, then stops it with SIGTERM; returns its exit status. */
int recordUntilMotionDone(const std::vector<std::string>& args, const std::string& log, std::thread& client)
{
	CBackgroundProcess grabber(args, log);
	client.join();
	std::this_thread::sleep_for(std::chrono::duration<double>(STILL_S));
	kill(grabber.pid(), SIGTERM);
	return grabber.wait(60.0);  // the live map is written after the stop
}

struct TRecording
{
	std::vector<mrpt::obs::CObservationOdometry::Ptr> odometry;
	std::vector<mrpt::obs::CObservationRange::Ptr> sonar;
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> laser;
	std::map<std::string, size_t> nonIncreasing;
	size_t entries = 0;
};

TRecording readRecording(const std::string& path)
{
	TRecording r;
	hslam::io::CRawlogReader reader(path);
	hslam::io::TRawlogEntry e;
	std::map<std::string, mrpt::Clock::time_point> last;
	while (reader.next(e))
	{
		++r.entries;
		if (!e.observation) continue;
		const auto& o = e.observation;
		if (last.count(o->sensorLabel) && !(o->timestamp > last[o->sensorLabel])) ++r.nonIncreasing[o->sensorLabel];
		last[o->sensorLabel] = o->timestamp;
		if (auto x = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o)) r.odometry.push_back(x);
		if (auto x = std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(o)) r.sonar.push_back(x);
		if (auto x = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) r.laser.push_back(x);
	}
	return r;
}

/** All the checks shared by both recorders. */
void checkRecording(const std::string& rawlog, const std::string& truthTum, const hslam::testing::CTempDir& tmp,
					const TWorldSetup& world)
{
	const TRecording r = readRecording(rawlog);
	const mrpt::poses::CPose2D& START = world.start;
	for (const auto& [label, n] : r.nonIncreasing) EXPECT_EQ(n, 0u) << "timestamps of " << label;

	// Odometry: ~10 Hz, follows the commanded arc, ends at the true pose.
	ASSERT_GE(r.odometry.size(), 40u);
	const auto& lastOdo = r.odometry.back()->odometry;
	const double arc = V_CMD * MOTION_S;
	EXPECT_NEAR(lastOdo.norm(), 2 * V_CMD / W_CMD * std::sin(W_CMD * MOTION_S / 2), 0.25 * arc);  // chord of the arc
	EXPECT_NEAR(lastOdo.phi(), W_CMD * MOTION_S, 0.25 * W_CMD * MOTION_S);
	EXPECT_NEAR(std::atan2(lastOdo.y(), lastOdo.x()), lastOdo.phi() / 2, 0.02);  // constant curvature
	const auto truth = hslam::common::readTumFile(truthTum);
	ASSERT_FALSE(truth.empty());
	const mrpt::poses::CPose2D trueEnd(truth.back().pose);
	const mrpt::poses::CPose2D recordedEnd = START + lastOdo;
	EXPECT_NEAR(recordedEnd.x(), trueEnd.x(), 0.003);
	EXPECT_NEAR(recordedEnd.y(), trueEnd.y(), 0.003);
	EXPECT_NEAR(mrpt::math::wrapToPi(recordedEnd.phi() - trueEnd.phi()), 0, 0.003);

	// Sonar: each SIP's ranges at that SIP's pose (same timestamp).
	std::map<mrpt::Clock::time_point, mrpt::poses::CPose2D> odoAt;
	for (const auto& o : r.odometry) odoAt[o->timestamp] = o->odometry;
	size_t sonarChecked = 0;
	double sonarSumErr = 0;
	size_t sonarReadings = 0, sonarOutside = 0;
	for (const auto& s : r.sonar)
	{
		const auto it = odoAt.find(s->timestamp);
		if (it == odoAt.end()) continue;
		const mrpt::poses::CPose2D robot = START + it->second;
		for (const auto& m : s->sensedData)
		{
			const mrpt::poses::CPose2D sp = robot + mrpt::poses::CPose2D(m.sensorPose.x, m.sensorPose.y, m.sensorPose.yaw);
			const double expected = std::min(5.0, world.ray(sp.x(), sp.y(), sp.phi(), 5.0));
			// Tolerance: 1 mm range units + the heading quantisation of the SIP
			// (2*pi/4096 rad, half of it as rounding error) over an oblique ray.
			const double tol = 0.0015 + expected * 0.5 * 2 * M_PI / 4096 * 3;
			const double err = std::abs(m.sensedDistance - expected);
			sonarOutside += err > tol;
			sonarSumErr += std::min(err, 0.1);
			++sonarReadings;
		}
		++sonarChecked;
	}
	EXPECT_GE(sonarChecked, 30u);
	// All readings within tolerance, except rays grazing an edge or a thin
	// chair leg, where the 1 mm / 0.088 deg pose quantisation flips hit/miss.
	EXPECT_LE(sonarOutside, sonarReadings / 100) << sonarOutside << " of " << sonarReadings;
	EXPECT_LT(sonarSumErr / std::max<size_t>(sonarReadings, 1), 0.003);

	// Laser: scans taken while the robot stood still after the motion.
	const auto stillSince = std::find_if(r.odometry.rbegin(), r.odometry.rend(),
										 [&](const auto& o) { return (o->odometry - lastOdo).norm() > 1e-6; });
	ASSERT_NE(stillSince, r.odometry.rend());
	const auto tStill = (*stillSince)->timestamp + std::chrono::milliseconds(300);
	size_t scansChecked = 0, beams = 0, beamsOutside = 0;
	for (const auto& s : r.laser)
	{
		if (s->timestamp < tStill) continue;
		ASSERT_EQ(s->getScanSize(), 361u);
		const mrpt::poses::CPose2D lp = trueEnd + mrpt::poses::CPose2D(s->sensorPose.x(), s->sensorPose.y(), s->sensorPose.yaw());
		for (size_t i = 0; i < s->getScanSize(); ++i)
		{
			const double a = lp.phi() - M_PI / 2 + i * M_PI / 360.0;
			const double expected = world.ray(lp.x(), lp.y(), a, 8.0);
			++beams;
			if (expected >= 8.0)  // no echo within the emulated 8 m: overflow value, invalid in MRPT
				beamsOutside += s->getScanRangeValidity(i);
			else  // cm mode: 5 mm rounding + pose quantisation
				beamsOutside += !s->getScanRangeValidity(i) || std::abs(s->getScanRange(i) - expected) > 0.0075 + 0.002 * expected;
		}
		++scansChecked;
	}
	EXPECT_GE(scansChecked, 5u);
	EXPECT_LE(beamsOutside, beams / 100) << beamsOutside << " of " << beams;

	// MRPT's rawlog-edit reads it; hslam-process maps it.
	const std::string info = tmp.file("info.txt");
	ASSERT_EQ(hslam::testing::runCommand("rawlog-edit --info -i '" + rawlog + "' > '" + info + "' 2>&1"), 0);
	const std::string infoText = readFile(info);
	EXPECT_NE(infoText.find("ODOMETRY"), std::string::npos) << infoText;
	EXPECT_NE(infoText.find("LASER"), std::string::npos) << infoText;
	EXPECT_NE(infoText.find("SONAR"), std::string::npos) << infoText;
	const std::string outDir = tmp.file("map"), processLog = tmp.file("process.txt");
	ASSERT_EQ(hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-process -q -i '" + rawlog + "' -o '" + outDir +
										 "' -c " + HSLAM_SOURCE_DIR + "/config_ini/hslam-default.ini > '" + processLog + "' 2>&1"),
			  0)
		<< readFile(processLog);
	EXPECT_GT(fs::file_size(outDir + "/map.png"), 100u);
}

std::string findRawlog(const hslam::testing::CTempDir& tmp)
{
	for (const auto& e : fs::directory_iterator(tmp.path()))
		if (e.path().extension() == ".rawlog") return e.path().string();
	return "";
}
}  // namespace

TEST(RecordingIntegration, MrptRawlogGrabberWithOurPlugin)
{
	hslam::testing::CTempDir tmp;
	const int port = teleopPort(0);
	const std::string ini = writeIni(tmp, port, false);
	const TWorldSetup world = boxRoom();
	auto emu = startEmulators(tmp, world);
	auto client = motionClient(port, 0.3, tmp.file("grabber.log"), tmp.file("motion.done"));
	// MRPT's grabber stops on a key on its standard input: sent once the
	// motion is over and the robot stood still for STILL_S (hang guard 60 s).
	const std::string stopper = "(for i in $(seq 600); do [ -e '" + tmp.file("motion.done") + "' ] && break; sleep 0.1; done; sleep " +
								std::to_string(STILL_S) + "; echo q)";
	const int rc = hslam::testing::runCommand(stopper + " | rawlog-grabber -p " + std::string(HSLAM_BINARY_DIR) +
											  "/lib/libhslam-hwdrivers-plugin.so '" + ini + "' > '" + tmp.file("grabber.log") +
											  "' 2>&1");
	client.join();
	EXPECT_EQ(rc, 0) << readFile(tmp.file("grabber.log"));
	EXPECT_EQ(emu->stop(SIGTERM), 0);  // writes truth.tum
	const std::string rawlog = findRawlog(tmp);
	ASSERT_FALSE(rawlog.empty()) << readFile(tmp.file("grabber.log"));
	checkRecording(rawlog, tmp.file("truth.tum"), tmp, world);
}

TEST(RecordingIntegration, HslamGrabberRecordsEverythingUntilTheStop)
{
	hslam::testing::CTempDir tmp;
	const int port = teleopPort(1);
	const std::string ini = writeIni(tmp, port, false);
	const TWorldSetup world = labScene();  // the simulator's world
	auto emu = startEmulators(tmp, world);
	auto client = motionClient(port, 0.3, tmp.file("grabber.log"));
	const std::string rawlog = tmp.file("ours.rawlog");
	const auto t0 = mrpt::Clock::now();
	// --duration is only a hang guard: the stop (SIGTERM) follows the motion.
	const int rc = recordUntilMotionDone({std::string(HSLAM_BIN_DIR) + "/hslam-grabber", ini, "--duration", "120", "-o", rawlog,
										  "--map-out", tmp.file("livemap")},
										 tmp.file("grabber.log"), client);
	const auto t1 = mrpt::Clock::now();
	const std::string log = readFile(tmp.file("grabber.log"));
	EXPECT_EQ(rc, 0) << log;
	std::cout << log;  // rates, throughput and CPU use
	EXPECT_EQ(emu->stop(SIGTERM), 0);
	checkRecording(rawlog, tmp.file("truth.tum"), tmp, world);
	// Nothing lost: one link (no outage), no gap in the odometry as long as the
	// driver's silence timeout (1 s; a longer one would have been an outage),
	// and the last odometry is from after the motion's end, within the silence
	// timeout of the moment the recorder stopped its sensors (stop_time=).
	const TRecording r = readRecording(rawlog);
	const auto pos = log.find("stop_time=");
	ASSERT_NE(pos, std::string::npos) << log;
	const double stopTime = std::stod(log.substr(pos + 10));
	EXPECT_LT(stopTime - mrpt::Clock::toDouble(r.odometry.back()->timestamp), 1.0);
	EXPECT_LT(stopTime, mrpt::Clock::toDouble(t1));
	double maxGap_s = 0;
	for (size_t i = 1; i < r.odometry.size(); ++i)
		maxGap_s = std::max(maxGap_s, mrpt::system::timeDifference(r.odometry[i - 1]->timestamp, r.odometry[i]->timestamp));
	EXPECT_LT(maxGap_s, 1.0);
	EXPECT_EQ(log.find("link up"), log.rfind("link up")) << log;
	EXPECT_GT(mrpt::system::timeDifference(t0, r.odometry.front()->timestamp), 0.0);
	EXPECT_TRUE(fs::exists(tmp.file("livemap") + "/map.png"));
}

TEST(RecordingIntegration, HslamGrabberStoppedBySigtermOrKilledLeavesAValidRawlog)
{
	for (int sig : {SIGTERM, SIGKILL})
	{
		hslam::testing::CTempDir tmp;
		const std::string ini = writeIni(tmp, 0, false);
		auto emu = startEmulators(tmp, boxRoom());
		const std::string rawlog = tmp.file("stop.rawlog");
		CBackgroundProcess grabber({std::string(HSLAM_BIN_DIR) + "/hslam-grabber", ini, "-o", rawlog}, tmp.file("g.log"));
		ASSERT_TRUE(grabber.waitForLog("link up", 30.0)) << grabber.log();
		// Until the recorder has flushed a good part of a second of data to
		// disk (behaviour, not wall time; hang guard 30 s).
		const auto guard = std::chrono::steady_clock::now() + std::chrono::seconds(30);
		while (std::chrono::steady_clock::now() < guard && !(fs::exists(rawlog) && fs::file_size(rawlog) > 20000))
			std::this_thread::sleep_for(std::chrono::milliseconds(50));
		kill(grabber.pid(), sig);
		const int rc = grabber.wait(30.0);
		size_t odo = 0, entries = 0;
		std::string error;
		try
		{
			hslam::io::CRawlogReader reader(rawlog);
			hslam::io::TRawlogEntry e;
			while (reader.next(e))
			{
				++entries;
				if (std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.observation)) ++odo;
			}
		}
		catch (const std::exception& e)
		{
			error = e.what();
		}
		if (sig == SIGTERM)
		{
			EXPECT_EQ(rc, 0) << grabber.log();
			EXPECT_EQ(error, "");  // complete gzip stream
			EXPECT_GE(odo, 5u);
		}
		else
		{
			// Killed: readable up to the last sync flush (GRABBER_PERIOD_MS 200
			// + hold 0.5 s), the cut tail reported as an error, no crash.
			EXPECT_GE(odo, 5u) << error;
		}
		EXPECT_GT(entries, odo);
	}
}

TEST(RecordingIntegration, SimulatorModelsDriveTheEmulatedRobot)
{
	// --sim-ini: the simulator's P3-DX kinematics with UMBmark errors and wheel
	// noise, its sonar model (30 deg cone, specular/multipath) and laser noise.
	hslam::testing::CTempDir tmp;
	const int port = teleopPort(2);
	const std::string ini = writeIni(tmp, port, false);
	TWorldSetup world = labScene();
	world.emulatorArgs.push_back("--sim-ini");
	world.emulatorArgs.push_back(std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-lab.ini");
	auto emu = startEmulators(tmp, world);
	auto client = motionClient(port, 0.2, tmp.file("grabber.log"));
	const std::string rawlog = tmp.file("simmodels.rawlog");
	const int rc = recordUntilMotionDone({std::string(HSLAM_BIN_DIR) + "/hslam-grabber", ini, "--duration", "120", "-o", rawlog},
										 tmp.file("grabber.log"), client);
	ASSERT_EQ(rc, 0) << readFile(tmp.file("grabber.log"));
	EXPECT_EQ(emu->stop(SIGTERM), 0);
	const TRecording r = readRecording(rawlog);
	ASSERT_GE(r.odometry.size(), 30u);

	// Odometry drifts from the truth (UMBmark + noise), but only a little.
	const auto truth = hslam::common::readTumFile(tmp.file("truth.tum"));
	ASSERT_FALSE(truth.empty());
	const mrpt::poses::CPose2D recordedEnd = world.start + r.odometry.back()->odometry;
	const double drift = (recordedEnd - mrpt::poses::CPose2D(truth.back().pose)).norm();
	EXPECT_GT(r.odometry.back()->odometry.norm(), 0.4);
	EXPECT_GT(drift, 1e-4);
	EXPECT_LT(drift, 0.05);

	// Sonar: most readings are the direct echo of the centre ray's wall, but
	// the cone and the specular model make some differ (the point of the model).
	std::map<mrpt::Clock::time_point, mrpt::poses::CPose2D> odoAt;
	for (const auto& o : r.odometry) odoAt[o->timestamp] = o->odometry;
	size_t near = 0, total = 0;
	for (const auto& s : r.sonar)
	{
		if (!odoAt.count(s->timestamp)) continue;
		const mrpt::poses::CPose2D robot = world.start + odoAt[s->timestamp];
		for (const auto& m : s->sensedData)
		{
			const mrpt::poses::CPose2D sp = robot + mrpt::poses::CPose2D(m.sensorPose.x, m.sensorPose.y, m.sensorPose.yaw);
			near += std::abs(m.sensedDistance - world.ray(sp.x(), sp.y(), sp.phi(), 5.0)) < 0.05;
			++total;
		}
	}
	ASSERT_GT(total, 200u);
	EXPECT_GT(near, total / 3) << near << " of " << total;
	EXPECT_LT(near, total) << "the sonar model should not be a single exact ray";

	// Laser, once the robot stands still at its (true) end pose: noisy (1 cm)
	// but centred on the world's ranges.
	const auto& lastOdo = r.odometry.back()->odometry;
	const auto stillSince = std::find_if(r.odometry.rbegin(), r.odometry.rend(),
										 [&](const auto& o) { return (o->odometry - lastOdo).norm() > 1e-6; });
	ASSERT_NE(stillSince, r.odometry.rend());
	const auto tStill = (*stillSince)->timestamp + std::chrono::milliseconds(300);
	const mrpt::poses::CPose2D trueEnd(truth.back().pose);
	std::vector<double> errors;
	for (const auto& s : r.laser)
	{
		if (s->timestamp < tStill) continue;
		const mrpt::poses::CPose2D lp = trueEnd + mrpt::poses::CPose2D(s->sensorPose.x(), 0, 0);
		for (size_t i = 0; i < s->getScanSize(); i += 5)
			if (s->getScanRangeValidity(i))
				errors.push_back(std::abs(s->getScanRange(i) - world.ray(lp.x(), lp.y(), lp.phi() - M_PI / 2 + i * M_PI / 360.0, 8.0)));
	}
	ASSERT_GT(errors.size(), 200u);
	std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
	EXPECT_LT(errors[errors.size() / 2], 0.015);  // median |N(0, 1 cm)| = 0.67 cm, + cm rounding
	EXPECT_GT(errors[errors.size() / 2], 0.001);  // not exact any more
}

TEST(RecordingIntegration, HslamGrabberKeyboardTeleopDrivesAndQuits)
{
	// hslam-grabber's standard input is a pseudo-terminal (a keyboard): 'w'
	// four times = 0.2 m/s forward, space = stop, 'q' = stop recording.
	hslam::testing::CTempDir tmp;
	const std::string ini = writeIni(tmp, 0, false);
	auto emu = startEmulators(tmp, boxRoom());
	CPseudoTerminal keyboard;
	keyboard.open(tmp.file("keyboard"));
	const std::string rawlog = tmp.file("teleop.rawlog");
	CBackgroundProcess grabber({std::string(HSLAM_BIN_DIR) + "/hslam-grabber", ini, "-o", rawlog, "--teleop", "keyboard"},
							   tmp.file("g.log"), keyboard.slavePath());
	ASSERT_TRUE(grabber.waitForLog("link up", 30.0)) << grabber.log();
	ASSERT_TRUE(grabber.waitForLog("teleop:", 10.0)) << grabber.log();
	const auto type = [&](const std::string& keys) { ASSERT_EQ(::write(keyboard.masterFd(), keys.data(), keys.size()), static_cast<ssize_t>(keys.size())); };
	type("wwww");
	std::this_thread::sleep_for(std::chrono::milliseconds(1500));
	type(" ");
	std::this_thread::sleep_for(std::chrono::milliseconds(500));
	type("q");
	EXPECT_EQ(grabber.wait(30.0), 0) << grabber.log();  // 'q' ended the recording cleanly
	const TRecording r = readRecording(rawlog);
	ASSERT_GE(r.odometry.size(), 10u);
	const auto& end = r.odometry.back()->odometry;
	// How long it drove depends on when the keys were read (machine load), so
	// the distance is checked against the motion recorded at 0.2 m/s: from
	// the first SIP moving to the first SIP stopped again (+- one SIP period).
	const auto moving = std::find_if(r.odometry.begin(), r.odometry.end(), [](const auto& o) { return o->velocityLocal.vx > 0.1; });
	ASSERT_NE(moving, r.odometry.end());
	const auto stopped = std::find_if(moving, r.odometry.end(), [](const auto& o) { return o->velocityLocal.vx < 1e-9; });
	ASSERT_NE(stopped, r.odometry.end());
	const double drove_s = mrpt::system::timeDifference((*moving)->timestamp, (*stopped)->timestamp);
	EXPECT_GT(end.x(), 0.05);
	EXPECT_NEAR(end.x(), 0.2 * drove_s, 0.2 * 0.25);  // straight ahead at the keyed speed
	EXPECT_NEAR(end.y(), 0.0, 0.002);
	EXPECT_NEAR(end.phi(), 0.0, 0.003);
	EXPECT_NEAR(r.odometry.back()->velocityLocal.vx, 0.0, 1e-9);  // stopped by the space bar
}
