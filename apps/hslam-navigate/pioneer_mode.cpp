/* hslam-navigate: real robot (see pioneer_mode.h). */
#include "pioneer_mode.h"

#include <hslam/hwdrivers/CPioneerSensor.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/hwdrivers/CGenericSensor.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/filesystem.h>

#include <chrono>
#include <iostream>
#include <thread>

namespace hslam::apps
{
namespace
{
/** Latest readings the controller needs, taken from a sensor's observation list. */
struct TLatest
{
	mrpt::math::TPose2D pose;
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationRange::Ptr sonar;
	bool havePose = false;
};

void collect(mrpt::hwdrivers::CGenericSensor& sensor, TLatest& latest, CNavigationLog& log)
{
	sensor.doProcess();
	mrpt::hwdrivers::CGenericSensor::TListObservations objs;
	sensor.getObservations(objs);
	for (const auto& [t, obj] : objs)
	{
		const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
		if (!obs) continue;
		log.observation(*obs);
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
			latest.pose = odo->odometry.asTPose(), latest.havePose = true;
		else if (auto scan = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(obs))
		{
			latest.scan = scan;
			if (latest.havePose) log.mapScan(*scan, latest.pose);
		}
		else if (auto sonar = std::dynamic_pointer_cast<mrpt::obs::CObservationRange>(obs))
			latest.sonar = sonar;
	}
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
	TLatest latest;
	TPioneerDriveResult res;
	const auto t0 = std::chrono::steady_clock::now();
	auto next = t0;
	try
	{
		while (!stopRequested)
		{
			collect(robot, latest, log);
			if (laser) collect(*laser, latest, log);
			res.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
			if (res.time_s > o.timeout_s) break;
			if (!latest.havePose) continue;
			const auto cmd = controller.step(latest.pose, latest.scan.get(), latest.sonar.get(), res.time_s);
			robot.driver().setVelocity(cmd.v_mps, cmd.w_rad_s);
			log.sample({res.time_s, latest.pose, cmd.v_mps, cmd.w_rad_s, nav::navStateName(cmd.state), cmd.nearest_m,
						cmd.targets_reached});
			res.targets_reached = cmd.targets_reached;
			if (cmd.state == nav::ENavState::target_reached)
			{
				res.finished = true;
				break;
			}
			next += std::chrono::duration_cast<std::chrono::steady_clock::duration>(
				std::chrono::duration<double>(o.control_period_s));
			std::this_thread::sleep_until(next);
		}
	}
	catch (...)
	{
		robot.driver().stop();
		robot.driver().spinOnce(0.05);
		throw;
	}
	robot.driver().stop();  // stop on every exit; the driver sends it on its next spin
	robot.driver().spinOnce(0.05);
	return res;
}

}  // namespace hslam::apps
