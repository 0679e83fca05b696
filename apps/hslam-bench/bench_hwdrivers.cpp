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
}  // namespace

int runHwdriversSuite(int repetitions)
{
	// 1. Parser throughput.
	std::vector<uint8_t> stream;
	std::mt19937 rng(3);
	const int nSips = 20000;
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
	size_t decoded = 0;
	const double tParse = bestTimeOf(repetitions, [&] {
		arcos::CArcosPacketParser parser;
		CArcosOdometry odo;
		std::vector<uint8_t> payload;
		decoded = 0;
		for (size_t i = 0; i < stream.size(); i += 64)
		{
			parser.feed(&stream[i], std::min<size_t>(64, stream.size() - i));
			while (parser.next(payload))
				if (auto s = arcos::decodeSip(payload))
				{
					odo.update(*s);
					++decoded;
				}
		}
	});
	const double sipsPerS = decoded / tParse;

	// 2. Driver over a pty at 10x the native SIP rate.
	const std::string dir = std::filesystem::temp_directory_path() / ("hslam_bench_hw_" + std::to_string(getpid()));
	std::filesystem::create_directories(dir);
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
	size_t received = 0;
	while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(3))
	{
		drv.setVelocity(0.2, 0.1);
		received += drv.spinOnce(0.02).size();
	}
	drv.stop();
	const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	const double drvCpu = rusageSeconds(RUSAGE_THREAD) - cpu0;
	const auto sent = emu.stats().sipsSent - sent0;
	drv.disconnect();
	emu.stop();

	// 3. Full recordings (emulators as a separate process).
	const std::string bin = exeDir();
	const std::string ini = dir + "/grab.ini";
	writeIni(ini, dir);
	const std::string emuCmd = bin + "/hslam-device-emulator --pioneer-pty " + dir + "/pioneer --lms200-pty " + dir +
							   "/lms --sip-period 0.01 --lms200-rate 75 --duration 9 > " + dir + "/emu.log 2>&1 &";
	struct TRun
	{
		std::string name;
		double cpu_s = 0, wall_s = 0, span_s = 0;
		std::map<std::string, size_t> labels;
	};
	std::vector<TRun> runs;
	for (const std::string which : {"hslam-grabber", "rawlog-grabber"})
	{
		if (std::system(emuCmd.c_str()) != 0) throw std::runtime_error("cannot start hslam-device-emulator");
		usleep(500000);
		TRun r;
		r.name = which;
		const std::string out = dir + "/ours.rawlog";
		const std::string cmd =
			which == "hslam-grabber"
				? bin + "/hslam-grabber " + ini + " --duration 6 -o " + out + " > " + dir + "/g.log 2>&1"
				: "(sleep 6; echo q) | rawlog-grabber -p " + bin + "/../lib/libhslam-hwdrivers-plugin.so " + ini + " > " +
					  dir + "/m.log 2>&1";
		const double c0 = rusageSeconds(RUSAGE_CHILDREN);
		const auto w0 = std::chrono::steady_clock::now();
		if (std::system(cmd.c_str()) != 0) std::cerr << which << " returned non-zero\n";
		r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
		r.cpu_s = rusageSeconds(RUSAGE_CHILDREN) - c0;
		std::string rawlog = out;
		if (which != "hslam-grabber")
			for (const auto& e : std::filesystem::directory_iterator(dir))
				if (e.path().filename().string().rfind("mrpt_", 0) == 0 && e.path().extension() == ".rawlog")
					rawlog = e.path().string();
		r.labels = countLabels(rawlog, r.span_s);
		runs.push_back(r);
		sleep(3);  // the emulator ends (--duration 9)
	}
	std::filesystem::remove_all(dir);

	std::cout << std::fixed << std::setprecision(2);
	std::cout << "ARCOS parser + SIP decoder: " << decoded << " SIPs (8 sonars, 5% garbage) in " << tParse * 1e3
			  << " ms = " << sipsPerS / 1e3 << " kSIP/s (" << sipsPerS / 10.0 << "x the native 10 SIP/s)\n";
	std::cout << "Driver over pty, SIP every 10 ms (10x native): sent " << sent << ", received " << received << " in "
			  << wall << " s, driver thread CPU " << 100.0 * drvCpu / wall << " % of one core\n";
	std::cout << "Recording (Pioneer SIPs at 100 Hz + LMS200 361 beams at 75 Hz):\n";
	std::cout << "  recorder          wall s   CPU %   obs/s   ODOMETRY Hz   LASER Hz\n";
	for (const auto& r : runs)
	{
		size_t total = 0;
		for (const auto& [l, n] : r.labels) total += n;
		const auto rate = [&](const char* l) { return r.labels.count(l) && r.span_s > 0 ? r.labels.at(l) / r.span_s : 0.0; };
		std::cout << "  " << std::setw(16) << std::left << r.name << std::right << std::setw(8) << r.wall_s
				  << std::setw(8) << 100.0 * r.cpu_s / r.wall_s << std::setw(8) << total / std::max(r.span_s, 1e-9)
				  << std::setw(14) << rate("ODOMETRY") << std::setw(11) << rate("LASER") << "\n";
	}
	std::cout << "parser_sips_per_s=" << sipsPerS << "\ndriver_sips_sent=" << sent << "\ndriver_sips_received=" << received
			  << "\ndriver_cpu_percent=" << 100.0 * drvCpu / wall << "\n";
	for (const auto& r : runs)
	{
		const std::string k = r.name == "hslam-grabber" ? "hslam_grabber" : "mrpt_grabber";
		double total = 0;
		for (const auto& [l, n] : r.labels) total += n;
		std::cout << k << "_cpu_percent=" << 100.0 * r.cpu_s / r.wall_s << "\n"
				  << k << "_obs_per_s=" << total / std::max(r.span_s, 1e-9) << "\n"
				  << k << "_odometry_hz=" << (r.labels.count("ODOMETRY") ? r.labels.at("ODOMETRY") / r.span_s : 0) << "\n"
				  << k << "_laser_hz=" << (r.labels.count("LASER") ? r.labels.at("LASER") / r.span_s : 0) << "\n";
	}
	return 0;
}

}  // namespace hslam::bench
