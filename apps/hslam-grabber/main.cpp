/* hslam-grabber: records a rawlog from the sensors of a rawlog-grabber INI file
 * (same [global] keys and sensor sections as MRPT's rawlog-grabber, same
 * CGenericSensor drivers: MRPT's built-ins, our CPioneerSensor, and any -p
 * plug-in), fixing what MRPT 2.5's rawlog-grabber gets wrong
 * (../shared/notes/mrpt-plugins-and-protocols.md s.1.4):
 *  - stops cleanly on Ctrl-C, SIGTERM, --duration or 'q' (teleop) and writes
 *    every observation received before the stop; the gzip stream is sync-flushed
 *    every GRABBER_PERIOD_MS so even a SIGKILL leaves a readable file;
 *  - correct odometry increments in sensory-frame mode (CSensoryFrameBuilder);
 *  - keyboard or joystick (MRPT's CJoystick) teleoperation of the Pioneer while
 *    recording (--teleop keyboard|joystick);
 *  - optional live mapping (--map-out DIR): the hslam mapping pipeline runs on
 *    the entries as they are written and the map is written at the stop.
 * Prints a summary with per-label rates, throughput and CPU use. */
#include "CJoystickTeleop.h"
#include "CKeyboardTeleop.h"
#include "CRecordingWriter.h"
#include "CSensorThread.h"

#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/version.h>
#include <hslam/hwdrivers/CPioneerSensor.h>
#include <hslam/slam/batch_outputs.h>
#include <hslam/slam/mapping_config.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/datetime.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/system/os.h>
#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <mutex>
#include <thread>

namespace
{
std::atomic<bool> g_stop{false};
void onSignal(int) { g_stop = true; }

/** [global] keys of rawlog-grabber (MRPT 2.5.8 RawlogGrabberApp). */
struct TGlobalOptions
{
	std::string rawlog_prefix = "dataset";
	int time_between_launches_ms = 300;
	bool use_sensoryframes = false;
	int grabber_period_ms = 1000;
	int compress_level = 1;
	double sf_max_time_span_s = 0.25;
	std::string max_queue_len;  // parsed by MRPT, unused (also ignored by MRPT 2.5.8)

	template <class V>
	void visit(V& v)
	{
		v.text("rawlog_prefix", rawlog_prefix);
		v.integer("time_between_launches", time_between_launches_ms, 0, 60000);
		v.flag("use_sensoryframes", use_sensoryframes);
		v.integer("GRABBER_PERIOD_MS", grabber_period_ms, 10, 60000);
		v.integer("rawlog_GZ_compress_level", compress_level, 0, 9);
		v.real("SF_max_time_span", sf_max_time_span_s, 0.001, 60.0);
		v.text("max_queue_len", max_queue_len);
	}
};

double cpuSeconds()
{
	rusage u{};
	getrusage(RUSAGE_SELF, &u);
	return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::string defaultOutput(const std::string& prefix)
{
	const auto t = std::time(nullptr);
	char buf[64];
	std::strftime(buf, sizeof(buf), "_%Y-%m-%d_%Hh%Mm%Ss.rawlog", std::localtime(&t));
	return prefix + buf;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TCLAP::CmdLine cmd("hslam-grabber: rawlog recorder reading rawlog-grabber INI files", ' ', hslam::common::versionText());
		TCLAP::UnlabeledValueArg<std::string> ini("config", "rawlog-grabber INI file", true, "", "grab.ini", cmd);
		TCLAP::ValueArg<std::string> plugins("p", "plugins", "comma-separated plug-in modules to load (default: none)", false, "", "a.so,b.so", cmd);
		TCLAP::ValueArg<std::string> out("o", "out", "output rawlog (default <rawlog_prefix>_<date>.rawlog)", false, "", "file", cmd);
		TCLAP::ValueArg<double> duration("", "duration", "stop after this many seconds (0 = Ctrl-C / SIGTERM / q) (default: 0)", false, 0, "s", cmd);
		TCLAP::ValueArg<std::string> teleop("", "teleop", "none | keyboard (w/s/a/d/space, q quits) | joystick (button 0 dead-man, button 1 quits) (default: none)", false, "none", "mode", cmd);
		TCLAP::ValueArg<int> joyIndex("", "joystick", "joystick index (/dev/input/js<N>) (default: 0)", false, 0, "N", cmd);
		TCLAP::ValueArg<double> joyMaxV("", "joystick-max-v", "speed at full stick (m/s) (default: 0.4)", false, 0.4, "m/s", cmd);
		TCLAP::ValueArg<double> joyMaxW("", "joystick-max-w", "turn rate at full stick (deg/s) (default: 40)", false, 40, "deg/s", cmd);
		TCLAP::ValueArg<double> vStep("", "teleop-v-step", "keyboard speed step (m/s) (default: 0.05)", false, 0.05, "m/s", cmd);
		TCLAP::ValueArg<double> wStep("", "teleop-w-step", "keyboard turn-rate step (deg/s) (default: 10)", false, 10, "deg/s", cmd);
		TCLAP::ValueArg<double> hold("", "hold", "reordering delay before writing (s) (default: 0.5)", false, 0.5, "s", cmd);
		TCLAP::ValueArg<std::string> mapOut("", "map-out", "run the mapping pipeline live, write the map here at the stop (default: none)", false, "", "dir", cmd);
		TCLAP::ValueArg<std::string> mapConfig("", "map-config", "pipeline INI (default config_ini/hslam-default.ini values)", false, "", "file", cmd);
		if (!cmd.parse(argc, argv)) return 0;
		if (teleop.getValue() != "none" && teleop.getValue() != "keyboard" && teleop.getValue() != "joystick")
			throw std::runtime_error("--teleop '" + teleop.getValue() + "': expected none, keyboard or joystick");

		if (!plugins.getValue().empty())
		{
			std::string errs;
			if (!mrpt::system::loadPluginModules(plugins.getValue(), errs))
				throw std::runtime_error("cannot load plug-in(s) '" + plugins.getValue() + "': " + errs);
		}
		hslam::hwdrivers::registerHwdriversSensors();

		const auto cfg = hslam::common::loadIniFile(ini.getValue());
		TGlobalOptions g;
		hslam::common::loadOptions(g, cfg, "global");
		const std::string outPath = out.getValue().empty() ? defaultOutput(g.rawlog_prefix) : out.getValue();

		// --map-config goes through the same loading, checks and path
		// resolution as hslam-process (TMappingConfig::fromConfig).
		std::unique_ptr<hslam::slam::CMappingPipeline> pipeline;
		hslam::slam::TOutputOptions mapOutOpts;
		if (!mapOut.getValue().empty())
		{
			const auto mapCfg = hslam::slam::TMappingConfig::fromConfig(mapConfig.getValue(), {});
			pipeline = std::make_unique<hslam::slam::CMappingPipeline>(mapCfg.ini);
			mapOutOpts = mapCfg.output;
		}
		else if (!mapConfig.getValue().empty())
			throw std::runtime_error("--map-config needs --map-out DIR (where the live map is written)");

		// Sensor sections (as rawlog-grabber: all but [global] and ignored ones);
		// the sensors only call the sink once started, after `writer` exists.
		std::unique_ptr<CRecordingWriter> writer;
		std::mutex sinkMtx;  // a sensor thread still blocked at the stop must not write after finish()
		bool sinkOpen = true;
		std::vector<std::string> sections;
		cfg.getAllSections(sections);
		std::vector<std::unique_ptr<CSensorThread>> threads;
		for (const auto& sec : sections)
		{
			if (sec == "global" || cfg.read_bool(sec, "rawlog-grabber-ignore", false)) continue;
			threads.push_back(std::make_unique<CSensorThread>(
				cfg, sec, [&writer, &sinkMtx, &sinkOpen](mrpt::hwdrivers::CGenericSensor::TListObservations&& o) {
					std::lock_guard<std::mutex> lk(sinkMtx);
					if (sinkOpen) writer->add(std::move(o));
				}));
		}
		if (threads.empty()) throw std::runtime_error(ini.getValue() + ": no sensor sections");
		// The output is created only once the configuration is known to be good.
		writer = std::make_unique<CRecordingWriter>(outPath, g.compress_level, g.use_sensoryframes, g.sf_max_time_span_s,
												   hold.getValue());
		writer->setPipeline(pipeline.get());

		std::signal(SIGINT, onSignal);
		std::signal(SIGTERM, onSignal);
		std::cerr << "hslam-grabber: recording " << threads.size() << " sensor(s) into " << outPath << "\n";
		const auto t0 = std::chrono::steady_clock::now();
		const double cpu0 = cpuSeconds();
		for (auto& t : threads)
		{
			t->start();
			std::this_thread::sleep_for(std::chrono::milliseconds(g.time_between_launches_ms));
		}

		std::unique_ptr<CKeyboardTeleop> keys;
		std::unique_ptr<CJoystickTeleop> joy;
		if (teleop.getValue() == "keyboard") keys = std::make_unique<CKeyboardTeleop>(vStep.getValue(), wStep.getValue() * M_PI / 180);
		if (teleop.getValue() == "joystick")
			joy = std::make_unique<CJoystickTeleop>(joyIndex.getValue(), joyMaxV.getValue(), joyMaxW.getValue() * M_PI / 180);
		const auto command = [&threads](double v, double w) {
			for (auto& t : threads)
				if (auto* p = dynamic_cast<hslam::hwdrivers::CPioneerSensor*>(&t->sensor())) p->driver().setVelocity(v, w);
		};
		std::string failure;
		auto nextWrite = std::chrono::steady_clock::now();
		while (!g_stop)
		{
			std::this_thread::sleep_for(std::chrono::milliseconds(50));
			if (keys && keys->active())
			{
				if (!keys->poll()) break;
				command(keys->v_mps(), keys->w_rad_s());
			}
			if (joy)
			{
				if (!joy->poll()) break;
				if (joy->active()) command(joy->v_mps(), joy->w_rad_s());
			}
			for (auto& t : threads)
				if (t->failed()) failure = t->error();
			if (!failure.empty()) break;
			const auto now = std::chrono::steady_clock::now();
			if (duration.getValue() > 0 && std::chrono::duration<double>(now - t0).count() >= duration.getValue()) break;
			if (now >= nextWrite)
			{
				writer->writeDue();
				nextWrite = now + std::chrono::milliseconds(g.grabber_period_ms);
			}
		}
		const double stopTime = mrpt::Clock::toDouble(mrpt::Clock::now());
		// A stop acts within 1 s (issue 15 item 6): a thread still blocked in a
		// driver (e.g. MRPT's LMS initialize() retrying a missing port) is left
		// behind and the process ends by _Exit once the rawlog is closed.
		std::vector<std::string> blocked;
		for (auto& t : threads)
			if (!t->stopWithin(1.0)) blocked.push_back(t->section());
		{
			std::lock_guard<std::mutex> lk(sinkMtx);
			sinkOpen = false;
		}
		writer->finish();
		const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		const double cpu = cpuSeconds() - cpu0;
		// Link outages of the Pioneer (the summary names them, issue 15 item 6).
		std::vector<std::string> outageLines;
		for (auto& t : threads)
			if (auto* p = dynamic_cast<hslam::hwdrivers::CPioneerSensor*>(&t->sensor()))
			{
				const auto st = p->driver().stats();
				std::ostringstream os;
				os << "  " << std::setw(12) << t->section() << ": link outages " << st.outages << ", total "
				   << st.outageTotal_s << " s, longest " << st.longestOutage_s << " s"
				   << (st.connected ? "" : "; link down at the stop: " + st.lastError) << "\n";
				outageLines.push_back(os.str());
			}
		if (blocked.empty()) threads.clear();

		std::cout << "hslam-grabber: wrote " << writer->objectsWritten() << " objects (" << writer->observationsWritten()
				  << " observations) to " << outPath << " in " << std::fixed << std::setprecision(2) << wall << " s\n";
		for (const auto& [label, st] : writer->labelStats())
		{
			const double span = st.last_s - st.first_s;
			std::cout << "  " << std::setw(12) << (label.empty() ? "(no label)" : label) << ": " << st.count << " obs, "
					  << (span > 0 ? (st.count - 1) / span : 0.0) << " Hz, non-increasing timestamps: " << st.nonIncreasing
					  << "\n";
		}
		for (const auto& line : outageLines) std::cout << line;
		if (pipeline)
		{
			const auto files = hslam::slam::writeMappingOutputs(*pipeline, mapOutOpts, mapOut.getValue());
			std::cout << "  live map: " << pipeline->counters().laser_scans << " scans mapped, " << files.size()
					  << " files in " << mapOut.getValue() << "\n";
		}
		std::cout << "objects=" << writer->objectsWritten() << "\nobservations=" << writer->observationsWritten()
				  << "\nwall_s=" << wall << "\ncpu_s=" << cpu << "\ncpu_percent=" << 100.0 * cpu / std::max(wall, 1e-9)
				  << "\nobservations_per_s=" << writer->observationsWritten() / std::max(wall, 1e-9) << "\n"
				  << std::setprecision(6) << "stop_time=" << stopTime << "\n";
		int code = 0;
		if (!failure.empty())
		{
			std::cerr << "hslam-grabber: stopped because a sensor failed: " << failure << "\n";
			code = 2;
		}
		if (!blocked.empty())
		{
			for (const auto& sec : blocked)
				std::cerr << "hslam-grabber: [" << sec << "] did not stop within 1 s (driver blocked); left behind\n";
			std::cout.flush();
			std::cerr.flush();
			std::_Exit(code);  // the blocked threads still use their objects: no destructors
		}
		return code;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-grabber: " << e.what() << "\n";
		return 1;
	}
}
