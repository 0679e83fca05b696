/* hslam: 2D trajectories and the TUM trajectory file format
 * ("timestamp tx ty tz qx qy qz qw" per line, '#' comments), used for
 * reference poses, estimates and evaluation. */
#pragma once

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace hslam::common
{
struct TTimedPose2D
{
	double t_s = 0;  //!< timestamp, seconds (UNIX epoch or a documented synthetic clock)
	mrpt::math::TPose2D pose;  //!< x, y (m), phi (rad)
};
using TTrajectory2D = std::vector<TTimedPose2D>;

/** Writes a TUM file (z = 0, rotation about z). Throws std::runtime_error
 * naming the file if it cannot be written. */
void writeTumFile(const std::string& path, const TTrajectory2D& trajectory);

/** Reads a TUM file; yaw is taken from the quaternion. Throws
 * std::runtime_error naming file and line for malformed content. */
TTrajectory2D readTumFile(const std::string& path);

/** Parses TUM text (for tests and in-memory use); `name` is used in errors. */
TTrajectory2D parseTum(const std::string& text, const std::string& name);

}  // namespace hslam::common
