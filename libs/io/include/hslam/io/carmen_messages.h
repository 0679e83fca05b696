/* hslam: the CARMEN log messages the importer understands, as plain structs.
 *
 * Field layouts (CARMEN logger, one message per text line):
 *   FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc_ts host logger_ts   (RLASER alike)
 *   ROBOTLASER1 type start_angle fov resolution max_range accuracy remission_mode
 *       n r1..rn m rem1..remm laser_x laser_y laser_theta robot_x robot_y robot_theta
 *       tv rv forward_safety side_safety turn_axis ipc_ts host logger_ts   (ROBOTLASER2 = rear)
 *   RAWLASER1..4 type start_angle fov resolution max_range accuracy remission_mode
 *       n r1..rn m rem1..remm ipc_ts host logger_ts                         (no pose)
 *   ODOM x y theta tv rv accel ipc_ts host logger_ts
 *   PARAM name value [ipc_ts host logger_ts]   (older logs: PARAM name value host ts)
 * Everything else (NEFF, SYNC, TRUEPOS, SONAR, '#' comments, ...) is skipped. */
#pragma once

#include <mrpt/math/TPose2D.h>

#include <cstddef>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace hslam::io
{
/** Both timestamps CARMEN writes: the sender's (IPC) clock and the logger's
 * clock. Either may be unusable in a given log (see carmen_clock.h). */
struct TCarmenStamp
{
	double ipc_s = 0;
	std::string host;
	double logger_s = 0;
};

/** Which physical laser a message belongs to. */
enum class TCarmenLaserRole
{
	lrFront,  //!< FLASER, ROBOTLASER1: carries the reference pose
	lrRear,  //!< RLASER, ROBOTLASER2
	lrRaw  //!< RAWLASER1..4: ranges only, no pose
};

/** Angular layout given explicitly by ROBOTLASER / RAWLASER messages. */
struct TCarmenLaserConfig
{
	double startAngle_rad = 0;  //!< direction of the first beam (sensor frame, CCW)
	double fov_rad = 0;
	double resolution_rad = 0;  //!< angle between consecutive beams
	double maxRange_m = 0;
};

struct TCarmenLaser
{
	std::string name;  //!< message name: "FLASER", "ROBOTLASER1", "RAWLASER2", ...
	TCarmenLaserRole role = TCarmenLaserRole::lrFront;
	int rawIndex = 0;  //!< 1..4 for RAWLASERk, else 0
	std::vector<double> ranges_m;
	std::optional<TCarmenLaserConfig> config;  //!< absent for FLASER/RLASER (guessed from n)
	/** FLASER: "x y theta"; ROBOTLASER: laser_x/y/theta. Absent for RAWLASER. */
	std::optional<mrpt::math::TPose2D> laserPose;
	/** FLASER: "odom_x odom_y odom_theta"; ROBOTLASER: robot_x/y/theta. */
	std::optional<mrpt::math::TPose2D> robotPose;
	double tv_mps = 0, rv_radps = 0;  //!< ROBOTLASER only
	TCarmenStamp stamp;
};

struct TCarmenOdometry
{
	mrpt::math::TPose2D pose;
	double tv_mps = 0, rv_radps = 0, accel_mps2 = 0;
	TCarmenStamp stamp;
};

struct TCarmenParam
{
	std::string name, value;
};

/** A line the importer does not use (its first word, "#" for comments). */
struct TCarmenSkipped
{
	std::string name;
};

using TCarmenMessage = std::variant<TCarmenLaser, TCarmenOdometry, TCarmenParam, TCarmenSkipped>;

/** Message name of any message ("FLASER", "ODOM", "PARAM", or the skipped word). */
std::string carmenMessageName(const TCarmenMessage& message);

}  // namespace hslam::io
