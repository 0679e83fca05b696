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

#include <hslam/common/command_line.h>
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

/** The command line. */
struct TGrabberArgs
{
	std::string ini, plugins, out, teleop = "none", map_out, map_config;
	double duration_s = 0, hold_s = 0.5;
	int joystick_index = 0;
	double joystick_max_v_mps = 0.4, joystick_max_w_radps = 0, keyboard_v_step_mps = 0.05, keyboard_w_step_radps = 0;
};

/** Parses argv into `a`; false if --help or --version was printed. */
bool parseArgs(int argc, char** argv, TGrabberArgs& a)
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
	if (!cmd.parse(argc, argv)) return false;
	if (teleop.getValue() != "none" && teleop.getValue() != "keyboard" && teleop.getValue() != "joystick")
		throw std::runtime_error("--teleop '" + teleop.getValue() + "': expected none, keyboard or joystick");
	a.ini = ini.getValue(), a.plugins = plugins.getValue(), a.out = out.getValue(), a.teleop = teleop.getValue();
	a.map_out = mapOut.getValue(), a.map_config = mapConfig.getValue();
	a.duration_s = duration.getValue(), a.hold_s = hold.getValue();
	a.joystick_index = joyIndex.getValue();
	a.joystick_max_v_mps = joyMaxV.getValue(), a.joystick_max_w_radps = joyMaxW.getValue() * M_PI / 180;
	a.keyboard_v_step_mps = vStep.getValue(), a.keyboard_w_step_radps = wStep.getValue() * M_PI / 180;
	return true;
}

void loadPlugins(const std::string& plugins)
{
	if (plugins.empty()) return;
	std::string errs;
	if (!mrpt::system::loadPluginModules(plugins, errs))
		throw std::runtime_error("cannot load plug-in(s) '" + plugins + "': " + errs);
}

/** --map-out: the pipeline fed with every written entry, and where its outputs go. */
struct TLiveMapping
{
	std::unique_ptr<hslam::slam::CMappingPipeline> pipeline;
	hslam::slam::TOutputOptions output;
};

/** --map-config goes through the same loading, checks and path resolution as
 * hslam-process (TMappingConfig::fromConfig). */
TLiveMapping makeLiveMapping(const TGrabberArgs& a)
{
	TLiveMapping m;
	if (a.map_out.empty())
	{
		if (!a.map_config.empty()) throw std::runtime_error("--map-config needs --map-out DIR (where the live map is written)");
		return m;
	}
	const auto mapCfg = hslam::slam::TMappingConfig::fromConfig(a.map_config, {});
	m.pipeline = std::make_unique<hslam::slam::CMappingPipeline>(mapCfg.ini);
	m.output = mapCfg.output;
	return m;
}

/** Where the sensor threads deliver: the writer, closed at the stop so that a
 * sensor thread still blocked at the stop does not write after finish(). */
class CRecordingSink
{
   public:
	void open(std::unique_ptr<CRecordingWriter> writer) { m_writer = std::move(writer); }
	void add(mrpt::hwdrivers::CGenericSensor::TListObservations&& o)
	{
		std::lock_guard<std::mutex> lk(m_mtx);
		if (m_open) m_writer->add(std::move(o));
	}
	void close()
	{
		std::lock_guard<std::mutex> lk(m_mtx);
		m_open = false;
	}
	CRecordingWriter& writer() { return *m_writer; }

   private:
	std::unique_ptr<CRecordingWriter> m_writer;
	std::mutex m_mtx;
	bool m_open = true;
};

using TSensorThreads = std::vector<std::unique_ptr<CSensorThread>>;

/** Sensor sections (as rawlog-grabber: all but [global] and ignored ones); the
 * sensors only call the sink once started, after its writer exists. */
TSensorThreads makeSensorThreads(const mrpt::config::CConfigFileBase& cfg, const std::string& iniPath, CRecordingSink& sink)
{
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	TSensorThreads threads;
	for (const auto& sec : sections)
	{
		if (sec == "global" || cfg.read_bool(sec, "rawlog-grabber-ignore", false)) continue;
		threads.push_back(std::make_unique<CSensorThread>(
			cfg, sec, [&sink](mrpt::hwdrivers::CGenericSensor::TListObservations&& o) { sink.add(std::move(o)); }));
	}
	if (threads.empty()) throw std::runtime_error(iniPath + ": no sensor sections");
	return threads;
}

/** Keyboard or joystick teleoperation of every Pioneer among the sensors. */
class CTeleop
{
   public:
	CTeleop(const TGrabberArgs& a, TSensorThreads& threads) : m_threads(threads)
	{
		if (a.teleop == "keyboard") m_keys = std::make_unique<CKeyboardTeleop>(a.keyboard_v_step_mps, a.keyboard_w_step_radps);
		if (a.teleop == "joystick")
			m_joy = std::make_unique<CJoystickTeleop>(a.joystick_index, a.joystick_max_v_mps, a.joystick_max_w_radps);
	}
	/** Reads the device and commands the Pioneers; false when the user quits. */
	bool poll()
	{
		if (m_keys && m_keys->active())
		{
			if (!m_keys->poll()) return false;
			command(m_keys->v_mps(), m_keys->w_rad_s());
		}
		if (m_joy)
		{
			if (!m_joy->poll()) return false;
			if (m_joy->active()) command(m_joy->v_mps(), m_joy->w_rad_s());
		}
		return true;
	}

   private:
	void command(double v_mps, double w_radps)
	{
		for (auto& t : m_threads)
			if (auto* p = dynamic_cast<hslam::hwdrivers::CPioneerSensor*>(&t->sensor())) p->driver().setVelocity(v_mps, w_radps);
	}

	TSensorThreads& m_threads;
	std::unique_ptr<CKeyboardTeleop> m_keys;
	std::unique_ptr<CJoystickTeleop> m_joy;
};

void startThreads(TSensorThreads& threads, int delay_ms)
{
	for (auto& t : threads)
	{
		t->start();
		std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
	}
}

/** Records until a signal, --duration, the teleop's quit or a failed sensor
 * (returns that sensor's error; empty otherwise), writing every GRABBER_PERIOD_MS. */
std::string recordUntilStop(const TGrabberArgs& a, const TGlobalOptions& g, TSensorThreads& threads,
							CRecordingWriter& writer, std::chrono::steady_clock::time_point t0)
{
	CTeleop teleop(a, threads);
	std::string failure;
	auto nextWrite = std::chrono::steady_clock::now();
	while (!g_stop)
	{
		std::this_thread::sleep_for(std::chrono::milliseconds(50));
		if (!teleop.poll()) break;
		for (auto& t : threads)
			if (t->failed()) failure = t->error();
		if (!failure.empty()) break;
		const auto now = std::chrono::steady_clock::now();
		if (a.duration_s > 0 && std::chrono::duration<double>(now - t0).count() >= a.duration_s) break;
		if (now >= nextWrite)
		{
			writer.writeDue();
			nextWrite = now + std::chrono::milliseconds(g.grabber_period_ms);
		}
	}
	return failure;
}

/** A stop acts within 1 s (issue 15 item 6): returns the sections whose thread
 * is still blocked in a driver (e.g. MRPT's LMS initialize() retrying a
 * missing port); they are left behind and the process ends by _Exit once the
 * rawlog is closed. */
std::vector<std::string> stopThreads(TSensorThreads& threads)
{
	std::vector<std::string> blocked;
	for (auto& t : threads)
		if (!t->stopWithin(1.0)) blocked.push_back(t->section());
	return blocked;
}

/** Link outages of each Pioneer, one summary line each (issue 15 item 6). */
std::vector<std::string> outageLines(TSensorThreads& threads)
{
	std::vector<std::string> lines;
	for (auto& t : threads)
		if (auto* p = dynamic_cast<hslam::hwdrivers::CPioneerSensor*>(&t->sensor()))
		{
			const auto st = p->driver().stats();
			std::ostringstream os;
			os << "  " << std::setw(12) << t->section() << ": link outages " << st.outages << ", total "
			   << st.outageTotal_s << " s, longest " << st.longestOutage_s << " s"
			   << (st.connected ? "" : "; link down at the stop: " + st.lastError) << "\n";
			lines.push_back(os.str());
		}
	return lines;
}

/** What a finished recording reports. */
struct TRecordingSummary
{
	std::string out_path;
	double wall_s = 0, cpu_s = 0, stop_time_s = 0;
	std::vector<std::string> outage_lines;
};

void printSummary(const TRecordingSummary& s, const CRecordingWriter& writer, TLiveMapping& live,
				  const std::string& mapOut)
{
	std::cout << "hslam-grabber: wrote " << writer.objectsWritten() << " objects (" << writer.observationsWritten()
			  << " observations) to " << s.out_path << " in " << std::fixed << std::setprecision(2) << s.wall_s << " s\n";
	for (const auto& [label, st] : writer.labelStats())
	{
		const double span = st.last_s - st.first_s;
		std::cout << "  " << std::setw(12) << (label.empty() ? "(no label)" : label) << ": " << st.count << " obs, "
				  << (span > 0 ? (st.count - 1) / span : 0.0) << " Hz, non-increasing timestamps: " << st.nonIncreasing
				  << "\n";
	}
	for (const auto& line : s.outage_lines) std::cout << line;
	if (live.pipeline)
	{
		live.pipeline->finish();  // readings still waiting for odometry, the map from the optimised graph
		const auto files = hslam::slam::writeMappingOutputs(*live.pipeline, live.output, mapOut);
		std::cout << "  live map: " << live.pipeline->counters().laser_scans << " scans mapped, " << files.size()
				  << " files in " << mapOut << "\n";
	}
	std::cout << "objects=" << writer.objectsWritten() << "\nobservations=" << writer.observationsWritten()
			  << "\nwall_s=" << s.wall_s << "\ncpu_s=" << s.cpu_s << "\ncpu_percent=" << 100.0 * s.cpu_s / std::max(s.wall_s, 1e-9)
			  << "\nobservations_per_s=" << writer.observationsWritten() / std::max(s.wall_s, 1e-9) << "\n"
			  << std::setprecision(6) << "stop_time=" << s.stop_time_s << "\n";
}

/** Exit code: 2 if a sensor failed; with blocked threads the process ends here
 * by _Exit (their objects are still in use: no destructors). */
int finishProcess(const std::string& failure, const std::vector<std::string>& blocked)
{
	int code = 0;
	if (!failure.empty())
	{
		std::cerr << "hslam-grabber: stopped because a sensor failed: " << failure << "\n";
		code = 2;
	}
	if (blocked.empty()) return code;
	for (const auto& sec : blocked)
		std::cerr << "hslam-grabber: [" << sec << "] did not stop within 1 s (driver blocked); left behind\n";
	std::cout.flush();
	std::cerr.flush();
	std::_Exit(code);
}

int record(const TGrabberArgs& a)
{
	loadPlugins(a.plugins);
	hslam::hwdrivers::registerHwdriversSensors();
	const auto cfg = hslam::common::loadIniFile(a.ini);
	TGlobalOptions g;
	hslam::common::loadOptions(g, cfg, "global");
	TRecordingSummary summary;
	summary.out_path = a.out.empty() ? defaultOutput(g.rawlog_prefix) : a.out;
	TLiveMapping live = makeLiveMapping(a);
	CRecordingSink sink;
	TSensorThreads threads = makeSensorThreads(cfg, a.ini, sink);
	// The output is created only once the configuration is known to be good.
	sink.open(std::make_unique<CRecordingWriter>(summary.out_path, g.compress_level, g.use_sensoryframes,
												 g.sf_max_time_span_s, a.hold_s));
	CRecordingWriter& writer = sink.writer();
	writer.setPipeline(live.pipeline.get());

	std::signal(SIGINT, onSignal);
	std::signal(SIGTERM, onSignal);
	std::cerr << "hslam-grabber: recording " << threads.size() << " sensor(s) into " << summary.out_path << "\n";
	const auto t0 = std::chrono::steady_clock::now();
	const double cpu0 = cpuSeconds();
	startThreads(threads, g.time_between_launches_ms);
	const std::string failure = recordUntilStop(a, g, threads, writer, t0);
	summary.stop_time_s = mrpt::Clock::toDouble(mrpt::Clock::now());
	const std::vector<std::string> blocked = stopThreads(threads);
	sink.close();
	writer.finish();
	summary.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	summary.cpu_s = cpuSeconds() - cpu0;
	summary.outage_lines = outageLines(threads);
	if (blocked.empty()) threads.clear();
	printSummary(summary, writer, live, a.map_out);
	return finishProcess(failure, blocked);
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TGrabberArgs args;
		if (!parseArgs(argc, argv, args)) return hslam::common::exitCodeAfterParseStop(argc, argv);  // help, version or a parse error
		return record(args);
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-grabber: " << e.what() << "\n";
		return 1;
	}
}
