/* hslam-grabber: sensor thread (see CSensorThread.h). */
#include "CSensorThread.h"

#include <chrono>
#include <stdexcept>

namespace
{
/** The readable part of an exception: MRPT wraps messages into a block with
 * "Message:", "Location:" and a call stack; keep only the message line. */
std::string shortMessage(const std::exception& e)
{
	const std::string full = mrpt::exception_to_str(e);
	const auto pos = full.find("Message:");
	if (pos == std::string::npos) return full;
	std::string msg = full.substr(pos + 8);
	msg = msg.substr(0, msg.find('\n'));
	const auto first = msg.find_first_not_of(' ');
	return first == std::string::npos ? full : msg.substr(first);
}
}  // namespace

CSensorThread::CSensorThread(const mrpt::config::CConfigFileBase& cfg, const std::string& section, TSink sink)
	: m_section(section), m_sink(std::move(sink))
{
	const std::string driver = cfg.read_string(section, "driver", "");
	if (driver.empty()) throw std::runtime_error("[" + section + "] has no 'driver' key");
	m_sensor = mrpt::hwdrivers::CGenericSensor::createSensorPtr(driver);
	if (!m_sensor)
		throw std::runtime_error("[" + section + "] driver = '" + driver +
								 "': unknown sensor class (missing plug-in? use -p libhslam-hwdrivers-plugin.so)");
	try
	{
		m_sensor->loadConfig(cfg, section);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error("[" + section + "] " + shortMessage(e));
	}
	if (!(m_sensor->getProcessRate() > 0)) throw std::runtime_error("[" + section + "] process_rate must be > 0 (Hz)");
}

CSensorThread::~CSensorThread() { stop(); }

void CSensorThread::start() { m_thread = std::thread([this] { run(); }); }

void CSensorThread::stop()
{
	m_quit = true;
	if (m_thread.joinable()) m_thread.join();
}

bool CSensorThread::stopWithin(double timeout_s)
{
	m_quit = true;
	const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
	while (!m_ended && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(10));
	if (!m_ended) return false;
	if (m_thread.joinable()) m_thread.join();
	return true;
}

std::string CSensorThread::error() const
{
	std::lock_guard<std::mutex> lk(m_mtx);
	return m_error;
}

void CSensorThread::run()
{
	using Clock = std::chrono::steady_clock;
	const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / m_sensor->getProcessRate()));
	try
	{
		m_sensor->initialize();
		auto next = Clock::now();
		while (!m_quit)
		{
			m_sensor->doProcess();
			mrpt::hwdrivers::CGenericSensor::TListObservations obs;
			m_sensor->getObservations(obs);
			if (!obs.empty()) m_sink(std::move(obs));
			next += period;
			const auto now = Clock::now();
			if (next < now)
				next = now;
			else
				std::this_thread::sleep_until(next);
		}
	}
	catch (const std::exception& e)
	{
		std::lock_guard<std::mutex> lk(m_mtx);
		m_error = "[" + m_section + "] " + shortMessage(e);
		m_failed = true;
	}
	// Whatever the sensor queued before the stop or the failure.
	mrpt::hwdrivers::CGenericSensor::TListObservations rest;
	m_sensor->getObservations(rest);
	if (!rest.empty()) m_sink(std::move(rest));
	m_ended = true;
}
