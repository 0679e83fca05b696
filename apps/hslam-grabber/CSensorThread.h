/* hslam-grabber: one MRPT CGenericSensor running in its own thread, as in
 * MRPT's rawlog-grabber (create by `driver` name, loadConfig, initialize, then
 * doProcess at process_rate), but stoppable: stop() makes the loop end after
 * its current doProcess, and the observations of that last call are still
 * collected, so nothing received before the stop is lost. */
#pragma once

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/hwdrivers/CGenericSensor.h>

#include <atomic>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

class CSensorThread
{
   public:
	using TSink = std::function<void(mrpt::hwdrivers::CGenericSensor::TListObservations&&)>;

	/** Creates and configures the sensor (throws with the section name on an
	 * unknown driver or bad configuration); does not start it. */
	CSensorThread(const mrpt::config::CConfigFileBase& cfg, const std::string& section, TSink sink);
	~CSensorThread();

	void start();
	/** Requests the stop and joins. */
	void stop();
	/** Requests the stop and joins if the thread ends within timeout_s;
	 * false if it is still blocked (a driver's initialize() retrying a missing
	 * port can block for tens of seconds): the caller then must not destroy
	 * this object and ends the process once the rawlog is closed. */
	bool stopWithin(double timeout_s);

	const std::string& section() const { return m_section; }
	mrpt::hwdrivers::CGenericSensor& sensor() { return *m_sensor; }
	/** Non-empty if the thread ended with an exception. */
	std::string error() const;
	bool failed() const { return m_failed; }

   private:
	void run();

	std::string m_section;
	mrpt::hwdrivers::CGenericSensor::Ptr m_sensor;
	TSink m_sink;
	std::thread m_thread;
	std::atomic<bool> m_quit{false}, m_failed{false}, m_ended{false};
	mutable std::mutex m_mtx;
	std::string m_error;
};
