/* hslam-navigate: real robot (see pioneer_mode.h). */
#include "pioneer_mode.h"

#include <hslam/hwdrivers/CPioneerSensor.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/datetime.h>
#include <mrpt/system/filesystem.h>

#include <atomic>
#include <algorithm>
#include <chrono>
#include <exception>
#include <memory>
#include <iostream>
#include <thread>

namespace hslam::apps
{
namespace
{
/** Latest readings the controller needs, taken from a sensor's observation list. */
struct TLatest
{
	mrpt::math::TPose2D pose, previousPose;
	mrpt::Clock::time_point poseTime, previousPoseTime;
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationRange::Ptr sonar;
	bool havePose = false, havePrevious = false;

	void setPose(const mrpt::math::TPose2D& p, mrpt::Clock::time_point t)
	{
		previousPose = pose, previousPoseTime = poseTime, havePrevious = havePose;
		pose = p, poseTime = t, havePose = true;
	}
	/** Odometry pose at time t, extrapolated from the last two readings (at
	 * most one SIP period ahead): a scan is mapped where the robot was when it
	 * arrived, not where the last SIP (up to 0.1 s older) put it. */
	mrpt::math::TPose2D poseAt(mrpt::Clock::time_point t) const
	{
		const double span = mrpt::system::timeDifference(previousPoseTime, poseTime);
		if (!havePrevious || span <= 1e-3) return pose;
		const double f = std::clamp(mrpt::system::timeDifference(poseTime, t) / span, 0.0, 1.0);
		return {pose.x + f * (pose.x - previousPose.x), pose.y + f * (pose.y - previousPose.y),
				mrpt::math::wrapToPi(pose.phi + f * mrpt::math::wrapToPi(pose.phi - previousPose.phi))};
	}
};

/** Runs one sensor's doProcess() in its own thread at its process_rate, as
 * rawlog-grabber does, so that every SIP and every laser frame is read and
 * stamped when it arrives. Read once per control period instead, a laser
 * frame that arrived just after the read waited a whole period and a second
 * one queued behind it (CSickLaserSerial reads one frame per call): the scans
 * were stamped 0.1 s or more late, smearing the walls of the live and the
 * batch maps in the driven run (docs/nav.md). */
class CSensorPump
{
   public:
	CSensorPump(mrpt::hwdrivers::CGenericSensor& sensor, double rate_hz)
		: m_sensor(sensor), m_period(1.0 / rate_hz), m_thread([this] { run(); })
	{
	}
	~CSensorPump() { stop(); }
	void stop()
	{
		m_stop = true;
		if (m_thread.joinable()) m_thread.join();
	}
	/** Rethrows in the caller what doProcess() threw in the thread. */
	void rethrowIfFailed() const
	{
		if (m_failed) std::rethrow_exception(m_error);
	}

   private:
	void run()
	{
		try
		{
			for (auto next = std::chrono::steady_clock::now(); !m_stop;)
			{
				m_sensor.doProcess();
				next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(m_period);
				std::this_thread::sleep_until(std::max(next, std::chrono::steady_clock::now()));
			}
		}
		catch (...)
		{
			m_error = std::current_exception();
			m_failed = true;
		}
	}
	mrpt::hwdrivers::CGenericSensor& m_sensor;
	std::chrono::duration<double> m_period;
	std::atomic<bool> m_stop{false}, m_failed{false};
	std::exception_ptr m_error;
	std::thread m_thread;
};

/** Takes what the sensors delivered since the last call, in time order. */
void collect(const std::vector<mrpt::hwdrivers::CGenericSensor*>& sensors, TLatest& latest, CNavigationLog& log)
{
	mrpt::hwdrivers::CGenericSensor::TListObservations all;
	for (auto* sensor : sensors)
	{
		mrpt::hwdrivers::CGenericSensor::TListObservations objs;
		sensor->getObservations(objs);
		all.insert(objs.begin(), objs.end());
	}
	for (const auto& [t, obj] : all)
	{
		const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
		if (!obs) continue;
		log.observation(*obs);
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
			latest.setPose(odo->odometry.asTPose(), odo->timestamp);
		else if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs))
		{
			latest.scan = scan;
			if (latest.havePose) log.mapScan(*scan, latest.poseAt(scan->timestamp));
		}
		else if (auto sonar = std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(obs))
			latest.sonar = sonar;
	}
}
}  // namespace

namespace
{
/** Steps the controller every control period on the latest readings. */
TPioneerDriveResult controlLoop(const TPioneerDriveOptions& o, nav::CSubsumptionController& controller,
								hwdrivers::CPioneerSensor& robot,
								const std::vector<mrpt::hwdrivers::CGenericSensor*>& sensors,
								const std::vector<std::unique_ptr<CSensorPump>>& pumps, CNavigationLog& log,
								const std::atomic<bool>& stopRequested)
{
	TLatest latest;
	TPioneerDriveResult res;
	const auto t0 = std::chrono::steady_clock::now();
	for (auto next = t0; !stopRequested;)
	{
		next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
			std::chrono::duration<double>(o.control_period_s));
		std::this_thread::sleep_until(next);
		for (const auto& p : pumps) p->rethrowIfFailed();
		collect(sensors, latest, log);
		res.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		if (res.time_s > o.timeout_s) break;
		if (!latest.havePose) continue;
		const auto cmd = controller.step(latest.pose, latest.scan.get(), latest.sonar.get(), res.time_s);
		robot.driver().setVelocity(cmd.v_mps, cmd.w_rad_s);
		log.sample({res.time_s, latest.pose, cmd.v_mps, cmd.w_rad_s, nav::navStateName(cmd.state), cmd.nearest_m,
					cmd.targets_reached, nav::navLayerName(cmd.layer)});
		res.targets_reached = cmd.targets_reached;
		if (cmd.state == nav::ENavState::target_reached)
		{
			res.finished = true;
			break;
		}
	}
	return res;
}
}  // namespace

TPioneerDriveResult drivePioneer(const TPioneerDriveOptions& o, const nav::TSubsumptionOptions& navOptions,
								 const std::vector<mrpt::math::TPoint2D>& targets, CNavigationLog& log,
								 const std::atomic<bool>& stopRequested)
{
	if (!mrpt::system::fileExists(o.ini)) throw std::runtime_error(o.ini + ": not found");
	mrpt::config::CConfigFile cfg(o.ini);
	hwdrivers::CPioneerSensor robot;
	robot.loadConfig(cfg, o.pioneer_section);
	robot.initialize();
	mrpt::hwdrivers::CGenericSensor::Ptr laser;
	if (!o.laser_section.empty())
	{
		const std::string driver = cfg.read_string(o.laser_section, "driver", "");
		laser = mrpt::hwdrivers::CGenericSensor::createSensorPtr(driver);
		if (!laser) throw std::runtime_error(o.ini + ": [" + o.laser_section + "] driver '" + driver + "' unknown");
		laser->loadConfig(cfg, o.laser_section);
		laser->initialize();
	}
	nav::CSubsumptionController controller(navOptions);
	controller.setTargets(targets);
	std::vector<mrpt::hwdrivers::CGenericSensor*> sensors{&robot};
	if (laser) sensors.push_back(laser.get());
	TPioneerDriveResult res;
	{
		// Threads reading the devices at their [section] process_rate; stopped
		// (joined) before the final stop command below.
		std::vector<std::unique_ptr<CSensorPump>> pumps;
		pumps.push_back(std::make_unique<CSensorPump>(robot, cfg.read_double(o.pioneer_section, "process_rate", 20)));
		if (laser)
			pumps.push_back(std::make_unique<CSensorPump>(*laser, cfg.read_double(o.laser_section, "process_rate", 30)));
		try
		{
			res = controlLoop(o, controller, robot, sensors, pumps, log, stopRequested);
		}
		catch (...)
		{
			pumps.clear();
			robot.driver().stop();
			robot.driver().spinOnce(0.05);
			throw;
		}
	}
	robot.driver().stop();  // stop on every exit; the driver sends it on its next spin
	robot.driver().spinOnce(0.05);
	return res;
}

}  // namespace hslam::apps
