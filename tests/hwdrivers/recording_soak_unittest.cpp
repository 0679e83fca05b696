/* Soak (issue 15): hslam-grabber records the device emulators while they
 * inject random faults (bad checksums, truncated SIPs, garbage, silences,
 * cable pulls) and is SIGKILLed at random moments, over and over. After each
 * kill the rawlog on disk must read back up to the last flush (no corrupt
 * entry before the cut, odometry stamps increasing, the data lost at the end
 * bounded by the flush interval + the reordering hold + one fault), and the
 * recorder's peak memory must stay bounded. Runs only when
 * HSLAM_SOAK_SECONDS is set (its duration; skipped in the normal suite):
 *   HSLAM_SOAK_SECONDS=90 build/bin/test_hwdrivers --gtest_filter='RecordingSoak.*'
 * Prints the figures (kills, faults, loss per kill, peak memory). */
#include <gtest/gtest.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include "background_process.h"

namespace
{
std::string readFile(const std::string& p)
{
	std::ifstream f(p);
	std::stringstream ss;
	ss << f.rdbuf();
	return ss.str();
}

/** Peak resident memory (VmHWM, kB) of a running process. */
long peakRss_kB(pid_t pid)
{
	std::ifstream f("/proc/" + std::to_string(pid) + "/status");
	for (std::string line; std::getline(f, line);)
		if (line.rfind("VmHWM:", 0) == 0) return std::stol(line.substr(6));
	return 0;
}

std::string writeIni(const hslam::testing::CTempDir& tmp)
{
	mrpt::config::CConfigFileMemory cfg(readFile(std::string(HSLAM_SOURCE_DIR) + "/config_ini/grabber-pioneer-lms200.ini"));
	cfg.write("global", "GRABBER_PERIOD_MS", "200");
	cfg.write("global", "time_between_launches", "100");
	cfg.write("global", "use_sensoryframes", "0");
	cfg.write("PIONEER", "COM_port_LIN", tmp.file("pioneer"));
	cfg.write("LASER", "COM_port_LIN", tmp.file("lms"));
	cfg.write("LASER", "nTries_connect", "1");
	const std::string path = tmp.file("soak.ini");
	std::ofstream(path) << cfg.getContent();
	return path;
}

struct TKillResult
{
	size_t odometry = 0, entries = 0;
	double lost_s = 0;  //!< kill time - last odometry stamp on disk (or the link-up time, if none)
	bool cleanPrefix = true;  //!< no corrupt entry before the cut
	bool increasing = true;
	std::string error;
};

/** Reads a killed recording back. `linkUp_s`: when the recorder reported its
 * link up; with no odometry on disk the loss counts from there (a kill inside
 * an injected silence or cable pull right after link-up records nothing, and
 * loses only what came after link-up). */
TKillResult readBack(const std::string& rawlog, double linkUp_s, double killTime_s)
{
	TKillResult r;
	double last = 0;
	try
	{
		hslam::io::CRawlogReader reader(rawlog);
		hslam::io::TRawlogEntry e;
		while (reader.next(e))
		{
			++r.entries;
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.observation))
			{
				const double t = mrpt::Clock::toDouble(o->timestamp);
				r.increasing = r.increasing && t > last;
				last = t;
				++r.odometry;
			}
		}
		r.cleanPrefix = reader.problems().empty();
	}
	catch (const hslam::io::rawlog_error& e)
	{
		r.error = e.what();  // the cut tail: expected after SIGKILL
	}
	r.lost_s = killTime_s - std::max(last, linkUp_s);
	return r;
}
}  // namespace

TEST(RecordingSoak, RandomFaultsAndKillsLoseAtMostTheFlushInterval)
{
	const char* env = std::getenv("HSLAM_SOAK_SECONDS");
	if (!env) GTEST_SKIP() << "soak test: set HSLAM_SOAK_SECONDS to run it";
	const double duration_s = std::atof(env);
	std::random_device rd;
	const unsigned seed = rd();
	std::mt19937 rng(seed);
	std::cout << "soak: seed " << seed << ", " << duration_s << " s\n";

	hslam::testing::CTempDir tmp;
	const std::string ini = writeIni(tmp);
	// Faults at random rates; silences of 1.5 s and cable pulls at intervals.
	std::uniform_real_distribution<double> rate(0.02, 0.1);
	const double silenceFor_s = 1.5;
	CBackgroundProcess emu({std::string(HSLAM_BIN_DIR) + "/hslam-device-emulator", "--pioneer-pty", tmp.file("pioneer"),
							"--lms200-pty", tmp.file("lms"), "--bad-checksum-rate", std::to_string(rate(rng)), "--partial-rate",
							std::to_string(rate(rng)), "--garbage-rate", std::to_string(rate(rng)), "--drop-every", "9",
							"--silence-every", "13", "--silence-for", std::to_string(silenceFor_s)},
						   tmp.file("emulator.log"));
	ASSERT_TRUE(emu.waitForLog("ready", 30.0)) << emu.log();

	// Loss bound: sync flush every 0.2 s + reordering hold 0.5 s + a SIP period,
	// + one silence (1.5 s) or cable pull (reconnect <= 1.5 s) just before the kill.
	const double lossBound_s = 0.2 + 0.5 + 0.1 + silenceFor_s + 1.5;
	const auto start = std::chrono::steady_clock::now();
	std::uniform_real_distribution<double> alive(1.0, 5.0);
	size_t kills = 0, odometry = 0, emptyKills = 0;
	double maxLost_s = 0, sumLost_s = 0;
	long maxRss_kB = 0;
	while (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < duration_s)
	{
		const std::string rawlog = tmp.file("kill" + std::to_string(kills) + ".rawlog");
		CBackgroundProcess grabber({std::string(HSLAM_BIN_DIR) + "/hslam-grabber", ini, "-o", rawlog}, tmp.file("g.log"));
		ASSERT_TRUE(grabber.waitForLog("link up", 30.0)) << grabber.log();
		const double linkUp_s = mrpt::Clock::toDouble(mrpt::Clock::now());
		std::this_thread::sleep_for(std::chrono::duration<double>(alive(rng)));
		maxRss_kB = std::max(maxRss_kB, peakRss_kB(grabber.pid()));
		const double killTime_s = mrpt::Clock::toDouble(mrpt::Clock::now());
		kill(grabber.pid(), SIGKILL);
		grabber.wait(10.0);
		const TKillResult r = readBack(rawlog, linkUp_s, killTime_s);
		EXPECT_TRUE(r.cleanPrefix) << rawlog;
		EXPECT_TRUE(r.increasing) << rawlog;
		emptyKills += r.odometry == 0 ? 1 : 0;
		EXPECT_LE(r.lost_s, lossBound_s) << rawlog << ": " << r.error;
		EXPECT_TRUE(r.error.empty() || r.error.find("truncated") != std::string::npos) << r.error;
		++kills;
		odometry += r.odometry;
		maxLost_s = std::max(maxLost_s, r.lost_s);
		sumLost_s += r.lost_s;
		std::filesystem::remove(rawlog);
	}
	const double minutes = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60.0;
	kill(emu.pid(), SIGTERM);
	emu.wait(10.0);
	const std::string emuLog = emu.log();
	const auto faults = emuLog.find("faults=");
	EXPECT_LT(maxRss_kB, 300 * 1024);  // the recorder's memory stays bounded
	ASSERT_GE(kills, 3u);
	EXPECT_LT(emptyKills, kills / 2) << "most recordings empty: the recorder is not recording";
	std::cout << "soak_minutes=" << minutes << "\nsoak_kills=" << kills << "\nsoak_odometry_recorded=" << odometry << "\nsoak_kills_with_nothing_recorded=" << emptyKills
			  << "\nsoak_faults_injected=" << (faults == std::string::npos ? std::string("?") : emuLog.substr(faults + 7, emuLog.find('\n', faults) - faults - 7))
			  << "\nsoak_lost_s_mean=" << sumLost_s / kills << "\nsoak_lost_s_max=" << maxLost_s
			  << "\nsoak_lost_observations_per_kill_max=" << maxLost_s * 10.0 << " (odometry at 10 Hz)"
			  << "\nsoak_peak_rss_MB=" << maxRss_kB / 1024.0 << "\n";
}
