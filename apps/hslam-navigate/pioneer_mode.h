/* hslam-navigate: driving the real P3-DX (or hslam-device-emulator) through
 * our Pioneer driver (libs/hwdrivers CPioneerSensor: ARCOS over serial or TCP,
 * odometry with the UMBmark correction of its section, sonar ring) and,
 * optionally, a laser read by any MRPT sensor driver from the same grabber INI
 * (e.g. CSickLaserSerial). The controller's (v, w) go to the driver every
 * control period; the driver's watchdog stops the robot if this program stops
 * sending, and the robot is stopped on every exit path. */
#pragma once

#include "CNavigationLog.h"

#include <atomic>

namespace hslam::apps
{
struct TPioneerDriveOptions
{
	std::string ini;  //!< grabber INI (rawlog-grabber / hslam-grabber style)
	std::string pioneer_section = "PIONEER";
	std::string laser_section;  //!< empty = sonar only
	double control_period_s = 0.1;
	double timeout_s = 300;
};

struct TPioneerDriveResult
{
	bool finished = false;
	size_t targets_reached = 0;
	double time_s = 0;
};

TPioneerDriveResult drivePioneer(const TPioneerDriveOptions& options, const nav::TSubsumptionOptions& navOptions,
								 const std::vector<mrpt::math::TPoint2D>& targets, CNavigationLog& log,
								 const std::atomic<bool>& stopRequested);

}  // namespace hslam::apps
