/* hslam-bench suite "hwdrivers": can the Pioneer driver keep up with the
 * robot's packet rate while the laser is recorded too, and at what CPU cost?
 *  1. ARCOS parser + SIP decoder throughput on a synthetic stream (8 sonars per
 *     SIP, 5 % garbage), compared with the native 10 SIP/s;
 *  2. the driver over a pseudo-terminal against the in-process emulator at
 *     10x the native rate (SIP every 10 ms): SIPs lost and driver-thread CPU;
 *  3. full recordings with hslam-device-emulator (Pioneer SIPs at 100 Hz, LMS200
 *     361-beam scans at 75 Hz, i.e. its 500 kbaud rate) by hslam-grabber and by
 *     MRPT's rawlog-grabber with our plug-in: observations/s and CPU use
 *     (children's rusage), plus the sensor rates found in the rawlog. */
#include <hslam/hwdrivers/CArcosEmulator.h>
#include <hslam/hwdrivers/CPioneerDriver.h>
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/arcos_sip.h>
#include <hslam/io/CRawlogReader.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>

#include "bench_common.h"
#include "bench_report.h"

namespace hslam::bench
{
namespace
{
using namespace hslam::hwdrivers;

double rusageSeconds(int who)
{
	rusage u{};
	getrusage(who, &u);
	return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string exeDir()
{
	return std::filesystem::read_symlink("/proc/self/exe").parent_path().string();
}

/** Label -> observations in a rawlog (observation format). */
std::map<std::string, size_t> countLabels(const std::string& path, double& span_s)
{
	std::map<std::string, size_t> n;
	hslam::io::CRawlogReader r(path);
	hslam::io::TRawlogEntry e;
	mrpt::Clock::time_point t0{}, t1{};
	while (r.next(e))
		if (e.observation)
		{
			++n[e.observation->sensorLabel];
			if (t0 == mrpt::Clock::time_point{}) t0 = e.observation->timestamp;
			t1 = std::max(t1, e.observation->timestamp);
		}
	span_s = mrpt::system::timeDifference(t0, t1);
	return n;
}

void writeIni(const std::string& path, const std::string& dir)
{
	FILE* f = std::fopen(path.c_str(), "w");
	std::fprintf(f,
				 "[global]\nrawlog_prefix = %s/mrpt\ntime_between_launches = 100\nuse_sensoryframes = 0\n"
				 "GRABBER_PERIOD_MS = 200\nrawlog_GZ_compress_level = 1\n"
				 "[PIONEER]\ndriver = CPioneerSensor\nprocess_rate = 200\nCOM_port_LIN = %s/pioneer\n"
				 "silence_timeout_s = 1.0\n"
				 "[LASER]\ndriver = CSickLaserSerial\nprocess_rate = 150\nsensorLabel = LASER\n"
				 "COM_port_LIN = %s/lms\nCOM_baudRate = 500000\nmm_mode = 0\nFOV = 180\nresolution = 50\n",
				 dir.c_str(), dir.c_str(), dir.c_str());
	std::fclose(f);
}
/** A synthetic ARCOS stream: nSips SIPs with 8 sonars each, 5 % followed by garbage bytes. */
std::vector<uint8_t> syntheticSipStream(int nSips)
{
	std::vector<uint8_t> stream;
	std::mt19937 rng(3);
	for (int k = 0; k < nSips; ++k)
	{
		arcos::TSip s;
		s.xpos_raw = static_cast<uint16_t>(k * 7);
		s.thpos_raw = static_cast<int16_t>(k % 4096 - 2048);
		s.has_tail = true;
		for (uint8_t i = 0; i < 8; ++i) s.sonars.push_back({i, static_cast<uint16_t>(500 + rng() % 4000)});
		const auto p = arcos::framePacket(arcos::encodeSip(s));
		stream.insert(stream.end(), p.begin(), p.end());
		if (rng() % 20 == 0)
			for (int g = 0; g < 10; ++g) stream.push_back(static_cast<uint8_t>(rng()));
	}
	return stream;
}

/** 1. Parser throughput: SIPs decoded, and the best time (s) to decode them in 64-byte reads. */
struct TParserThroughput
{
	size_t decoded = 0;
	double best_s = 0;
	double sipsPerS() const { return decoded / best_s; }
};

TParserThroughput measureParser(int repetitions)
{
	const std::vector<uint8_t> stream = syntheticSipStream(20000);
	TParserThroughput r;
	r.best_s = bestTimeOf(repetitions, [&] {
		arcos::CArcosPacketParser parser;
		CArcosOdometry odo;
		std::vector<uint8_t> payload;
		r.decoded = 0;
		for (size_t i = 0; i < stream.size(); i += 64)
		{
			parser.feed(&stream[i], std::min<size_t>(64, stream.size() - i));
			while (parser.next(payload))
				if (auto s = arcos::decodeSip(payload))
				{
					odo.update(*s);
					++r.decoded;
				}
		}
	});
	return r;
}

/** 2. The driver over a pty against the in-process emulator. */
struct TDriverLoad
{
	uint64_t sent = 0;
	size_t received = 0;
	double wall_s = 0, cpu_s = 0;  //!< driver thread CPU
	double cpuPercent() const { return 100.0 * cpu_s / wall_s; }
};

/** The driver for 3 s against the emulator sending a SIP every 10 ms (10x the native rate). */
TDriverLoad measureDriverOverPty(const std::string& dir)
{
	CArcosEmulator::TOptions eo;
	eo.pty_link = dir + "/pioneer_inproc";
	eo.sip_period_s = 0.01;
	auto world = std::make_shared<CBoxWorld>(CBoxWorld::TBox{-2, -3, 6, 3});
	CArcosEmulator emu(eo, world);
	emu.start();
	CPioneerDriver::TOptions dopt;
	dopt.serial_port = eo.pty_link;
	CPioneerDriver drv(dopt);
	drv.connect();
	const auto sent0 = emu.stats().sipsSent;
	const double cpu0 = rusageSeconds(RUSAGE_THREAD);
	const auto t0 = std::chrono::steady_clock::now();
	TDriverLoad r;
	while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(3))
	{
		drv.setVelocity(0.2, 0.1);
		r.received += drv.spinOnce(0.02).size();
	}
	drv.stop();
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	r.cpu_s = rusageSeconds(RUSAGE_THREAD) - cpu0;
	r.sent = emu.stats().sipsSent - sent0;
	drv.disconnect();
	emu.stop();
	return r;
}

/** 3. One recorder's run: its CPU (children's rusage), wall time and what the rawlog holds. */
struct TRecording
{
	std::string name;
	double cpu_s = 0, wall_s = 0, span_s = 0;
	std::map<std::string, size_t> labels;
	double observationsPerS() const
	{
		size_t total = 0;
		for (const auto& [l, n] : labels) total += n;
		return total / std::max(span_s, 1e-9);
	}
	double rate_hz(const char* label) const { return labels.count(label) && span_s > 0 ? labels.at(label) / span_s : 0.0; }
	/** Key prefix of the key=value lines. */
	std::string key() const { return name == "hslam-grabber" ? "hslam_grabber" : "mrpt_grabber"; }
};

/** The rawlog a recorder wrote: ours at `ours`, rawlog-grabber's named mrpt_*.rawlog in dir. */
std::string recordedRawlog(const std::string& recorder, const std::string& dir, const std::string& ours)
{
	if (recorder == "hslam-grabber") return ours;
	std::string rawlog = ours;
	for (const auto& e : std::filesystem::directory_iterator(dir))
		if (e.path().filename().string().rfind("mrpt_", 0) == 0 && e.path().extension() == ".rawlog")
			rawlog = e.path().string();
	return rawlog;
}

/** hslam-grabber or MRPT's rawlog-grabber (with our plug-in) recording 6 s from
 * hslam-device-emulator run as a separate process (SIPs at 100 Hz, LMS200 at 75 Hz). */
TRecording recordWith(const std::string& recorder, const std::string& dir)
{
	const std::string bin = exeDir(), ini = dir + "/grab.ini";
	writeIni(ini, dir);
	const std::string emuCmd = bin + "/hslam-device-emulator --pioneer-pty " + dir + "/pioneer --lms200-pty " + dir +
							   "/lms --sip-period 0.01 --lms200-rate 75 --duration 9 > " + dir + "/emu.log 2>&1 &";
	if (std::system(emuCmd.c_str()) != 0) throw std::runtime_error("cannot start hslam-device-emulator");
	usleep(500000);
	TRecording r;
	r.name = recorder;
	const std::string out = dir + "/ours.rawlog";
	const std::string cmd =
		recorder == "hslam-grabber"
			? bin + "/hslam-grabber " + ini + " --duration 6 -o " + out + " > " + dir + "/g.log 2>&1"
			: "(sleep 6; echo q) | rawlog-grabber -p " + bin + "/../lib/libhslam-hwdrivers-plugin.so " + ini + " > " +
				  dir + "/m.log 2>&1";
	const double c0 = rusageSeconds(RUSAGE_CHILDREN);
	const auto w0 = std::chrono::steady_clock::now();
	if (std::system(cmd.c_str()) != 0) std::cerr << recorder << " returned non-zero\n";
	r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
	r.cpu_s = rusageSeconds(RUSAGE_CHILDREN) - c0;
	r.labels = countLabels(recordedRawlog(recorder, dir, out), r.span_s);
	sleep(3);  // the emulator ends (--duration 9)
	return r;
}

void printHwdriversReport(const TParserThroughput& parser, const TDriverLoad& driver, const std::vector<TRecording>& runs)
{
	const double sipsPerS = parser.sipsPerS();
	std::cout << "ARCOS parser + SIP decoder: " << parser.decoded << " SIPs (8 sonars, 5% garbage) in "
			  << fixed(parser.best_s * 1e3, 2) << " ms = " << fixed(sipsPerS / 1e3, 2) << " kSIP/s ("
			  << fixed(sipsPerS / 10.0, 2) << "x the native 10 SIP/s)\n";
	std::cout << "Driver over pty, SIP every 10 ms (10x native): sent " << driver.sent << ", received " << driver.received
			  << " in " << fixed(driver.wall_s, 2) << " s, driver thread CPU " << fixed(driver.cpuPercent(), 2)
			  << " % of one core\n";
	std::cout << "Recording (Pioneer SIPs at 100 Hz + LMS200 361 beams at 75 Hz):\n";
	const CReportTable table(std::cout, {{"  recorder", 18, true},
										 {"wall s", 8},
										 {"CPU %", 8},
										 {"obs/s", 8},
										 {"ODOMETRY Hz", 14},
										 {"LASER Hz", 11}});
	table.printHeader();
	for (const auto& r : runs)
		table.printRow({"  " + r.name, fixed(r.wall_s, 2), fixed(100.0 * r.cpu_s / r.wall_s, 2),
						fixed(r.observationsPerS(), 2), fixed(r.rate_hz("ODOMETRY"), 2), fixed(r.rate_hz("LASER"), 2)});
	CKeyValueLines keys(std::cout);
	keys("parser_sips_per_s", fixed(sipsPerS, 2))("driver_sips_sent", driver.sent)(
		"driver_sips_received", driver.received)("driver_cpu_percent", fixed(driver.cpuPercent(), 2));
	for (const auto& r : runs)
		keys(r.key() + "_cpu_percent", fixed(100.0 * r.cpu_s / r.wall_s, 2))(
			r.key() + "_obs_per_s", fixed(r.observationsPerS(), 2))(r.key() + "_odometry_hz", fixed(r.rate_hz("ODOMETRY"), 2))(
			r.key() + "_laser_hz", fixed(r.rate_hz("LASER"), 2));
}
}  // namespace

int runHwdriversSuite(int repetitions)
{
	const TParserThroughput parser = measureParser(repetitions);
	const std::string dir = std::filesystem::temp_directory_path() / ("hslam_bench_hw_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
	const TDriverLoad driver = measureDriverOverPty(dir);
	std::vector<TRecording> runs;
	for (const std::string recorder : {"hslam-grabber", "rawlog-grabber"}) runs.push_back(recordWith(recorder, dir));
	std::filesystem::remove_all(dir);
	printHwdriversReport(parser, driver, runs);
	return 0;
}

}  // namespace hslam::bench
