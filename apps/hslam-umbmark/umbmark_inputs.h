/* hslam-umbmark: the three inputs of a UMBmark evaluation (thesis 4.1).
 *  - a simulator output folder: waypoints.csv (true and odometry pose at every
 *    corner) and ground_truth.tum (its first pose is the start);
 *  - a recording: the odometry of a rawlog, with the true poses from a TUM file
 *    interpolated at the odometry timestamps;
 *  - end-point errors typed in as CSV, like thesis tables 1-2:
 *    "group,direction,x_<unit>,y_<unit>" (unit m, cm or mm; direction cw/ccw). */
#pragma once

#include <hslam/calib/umbmark_runs.h>

#include <map>
#include <string>
#include <vector>

namespace hslam::apps
{
/** Start pose + corners of a simulator UMBmark folder. Throws std::runtime_error naming file and line. */
std::vector<calib::TPosePair> readWaypointFolder(const std::string& folder);

/** Every odometry reading of `rawlogPath` with the truth of `tumPath` at its time. */
std::vector<calib::TPosePair> readRawlogWithTruth(const std::string& rawlogPath, const std::string& tumPath);

/** End-point errors per group (first column), in file order of the groups. */
struct TEndpointTable
{
	std::vector<std::string> groups;
	std::map<std::string, std::vector<calib::TUmbmarkEndpoint>> runs;
};
TEndpointTable readEndpointCsv(const std::string& path);

}  // namespace hslam::apps
