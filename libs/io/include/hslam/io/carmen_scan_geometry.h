/* hslam: angular layout and mounting of CARMEN laser scans in MRPT terms.
 *
 * CARMEN's log reader (carmen_string_to_laser_laser_message_orig in
 * readlog.c) puts the first FLASER/RLASER beam at -90 deg and steps 1 deg for
 * 180/181 beams, 0.5 deg for 360/361 beams, counter-clockwise. So 180- and
 * 360-beam scans span 179 / 179.5 deg and are NOT centred on the heading.
 * MRPT spreads beams evenly over `aperture`, centred on the sensor heading
 * (rightToLeft = true: beam i at -aperture/2 + i * aperture/(n-1)). Hence
 * aperture = (n-1) * step and the sensor yaw gets the centring offset
 * firstBeam + aperture/2 (-0.5 deg for 180 beams, 0 for 181 and 361).
 * ROBOTLASER / RAWLASER messages carry start_angle and angular_resolution,
 * which are used as they are. The measured logs have 180, 181, 360 or 361
 * beams; for any other FLASER count 1 deg (n <= 181) or 0.5 deg is assumed
 * and a warning is returned.
 *
 * Mounting (PARAM, metres / radians): robot_frontlaser_offset (x),
 * robot_frontlaser_side_offset (y), robot_frontlaser_angular_offset (yaw) and
 * the robot_rearlaser_* ones, the rear laser looking backwards (yaw + pi).
 * ROBOTLASER messages carry both the laser and the robot pose, so their
 * mounting is robot_pose^-1 (+) laser_pose. RAWLASER1 is taken as the front
 * and RAWLASER2 as the rear laser (CARMEN's usual numbering), RAWLASER3/4 at
 * the robot origin. */
#pragma once

#include <hslam/io/carmen_log.h>
#include <hslam/io/carmen_messages.h>

#include <mrpt/poses/CPose3D.h>

#include <map>
#include <optional>
#include <string>

namespace hslam::io
{
struct TCarmenScanGeometry
{
	double aperture_rad = 0;  //!< (n-1) * step
	double centreYaw_rad = 0;  //!< direction of the middle of the fan in the laser frame
	std::optional<std::string> warning;  //!< set when the layout had to be guessed
};

/** Planar mounting of a laser on the robot. */
struct TCarmenLaserMount
{
	double x_m = 0, y_m = 0, yaw_rad = 0;
};

/** The front and rear mountings given by the PARAM lines of a log. */
struct TCarmenLaserMounts
{
	TCarmenLaserMount front, rear;
};

TCarmenScanGeometry carmenScanGeometry(const TCarmenLaser& laser);

/** Reads the mounting PARAMs (absent ones are 0). Throws std::runtime_error
 * "file:line: ..." if one of them is not a number. */
TCarmenLaserMounts carmenLaserMounts(const std::map<std::string, TCarmenParamValue>& params,
									 const std::string& path);

/** MRPT sensor pose of a scan: its mounting plus the centring yaw offset. */
mrpt::poses::CPose3D carmenSensorPose(const TCarmenLaser& laser, const TCarmenLaserMounts& mounts,
									  const TCarmenScanGeometry& geometry);

}  // namespace hslam::io
