/* hslam-umbmark: readers of the UMBmark inputs (see umbmark_inputs.h). */
#include "umbmark_inputs.h"

#include <hslam/common/parse_number.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/io/csv_line.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hslam::apps
{
namespace
{
/** The cells of a CSV line (io::splitCsvLine), trimmed. */
std::vector<std::string> splitCsv(const std::string& line)
{
	std::vector<std::string> out = io::splitCsvLine(line);
	for (auto& cell : out) cell = common::trim(cell);
	return out;
}

double number(const std::string& text, const std::string& where)
{
	const auto v = common::tryParseDouble(text);
	if (!v) throw std::runtime_error(where + ": not a number: '" + text + "'");
	return *v;
}

std::ifstream openOrThrow(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error(path + ": cannot be opened");
	return in;
}

mrpt::poses::CPose2D poseOf(const common::TTimedPose2D& p) { return mrpt::poses::CPose2D(p.pose); }

/** Pose of `traj` at time t (linear in x, y and the wrapped heading). */
mrpt::poses::CPose2D interpolate(const common::TTrajectory2D& traj, double t, const std::string& name)
{
	if (traj.empty() || t < traj.front().t_s - 0.05 || t > traj.back().t_s + 0.05)
		throw std::runtime_error(name + ": no true pose at odometry time " + std::to_string(t));
	auto it = std::lower_bound(traj.begin(), traj.end(), t, [](const auto& p, double v) { return p.t_s < v; });
	if (it == traj.begin()) return poseOf(*it);
	if (it == traj.end()) return poseOf(traj.back());
	const auto& a = *(it - 1);
	const auto& b = *it;
	const double f = b.t_s > a.t_s ? (t - a.t_s) / (b.t_s - a.t_s) : 0.0;
	const double dphi = mrpt::math::wrapToPi(b.pose.phi - a.pose.phi);
	return mrpt::poses::CPose2D(a.pose.x + f * (b.pose.x - a.pose.x), a.pose.y + f * (b.pose.y - a.pose.y),
								mrpt::math::wrapToPi(a.pose.phi + f * dphi));
}
}  // namespace

std::vector<calib::TPosePair> readWaypointFolder(const std::string& folder)
{
	const std::string csvPath = (std::filesystem::path(folder) / "waypoints.csv").string();
	const std::string tumPath = (std::filesystem::path(folder) / "ground_truth.tum").string();
	const auto truth = common::readTumFile(tumPath);
	if (truth.empty()) throw std::runtime_error(tumPath + ": no pose (the first one is the start of the first run)");
	// The simulator starts odometry at the true start pose.
	std::vector<calib::TPosePair> out{{truth.front().t_s, poseOf(truth.front()), poseOf(truth.front())}};
	auto in = openOrThrow(csvPath);
	std::string line;
	std::getline(in, line);
	if (splitCsv(line).size() != 8 || splitCsv(line)[2] != "true_x_m")
		throw std::runtime_error(csvPath + ":1: expected the header waypoint,t_s,true_x_m,true_y_m,true_yaw_deg,"
										   "odometry_x_m,odometry_y_m,odometry_yaw_deg");
	for (int lineNo = 2; std::getline(in, line); ++lineNo)
	{
		if (common::trim(line).empty()) continue;
		const auto c = splitCsv(line);
		const std::string where = csvPath + ":" + std::to_string(lineNo);
		if (c.size() != 8) throw std::runtime_error(where + ": expected 8 columns, got " + std::to_string(c.size()));
		const double d2r = M_PI / 180.0;
		out.push_back({number(c[1], where),
					   mrpt::poses::CPose2D(number(c[2], where), number(c[3], where), number(c[4], where) * d2r),
					   mrpt::poses::CPose2D(number(c[5], where), number(c[6], where), number(c[7], where) * d2r)});
	}
	return out;
}

std::vector<calib::TPosePair> readRawlogWithTruth(const std::string& rawlogPath, const std::string& tumPath)
{
	const auto truth = common::readTumFile(tumPath);
	io::CRawlogReader reader(rawlogPath);
	io::TRawlogEntry e;
	std::vector<calib::TPosePair> out;
	mrpt::poses::CPose2D accumulated;  // for actions + sensory-frame rawlogs
	while (reader.next(e))
	{
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.observation))
		{
			const double t = mrpt::Clock::toDouble(odo->timestamp);
			out.push_back({t, interpolate(truth, t, tumPath), odo->odometry});
		}
		if (!e.actions) continue;
		if (auto mv = e.actions->getBestMovementEstimation())
		{
			accumulated = accumulated + mv->poseChange->getMeanVal();
			const double t = mrpt::Clock::toDouble(mv->timestamp);
			out.push_back({t, interpolate(truth, t, tumPath), accumulated});
		}
	}
	if (out.size() < 5) throw std::runtime_error(rawlogPath + ": fewer than 5 odometry readings");
	// Odometry and truth need not share an origin: express odometry from the truth start.
	const mrpt::poses::CPose2D trueStart = out.front().truth, odometryStart = out.front().odometry;
	for (auto& p : out) p.odometry = trueStart + (p.odometry - odometryStart);
	return out;
}

TEndpointTable readEndpointCsv(const std::string& path)
{
	auto in = openOrThrow(path);
	std::string line;
	std::getline(in, line);
	const auto header = splitCsv(line);
	const std::map<std::string, double> units{{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}};
	double scale = 0;
	for (const auto& [u, s] : units)
		if (header.size() == 4 && header[2] == "x_" + u && header[3] == "y_" + u) scale = s;
	if (scale == 0) throw std::runtime_error(path + ":1: expected the header group,direction,x_<m|cm|mm>,y_<m|cm|mm>");
	TEndpointTable table;
	for (int lineNo = 2; std::getline(in, line); ++lineNo)
	{
		if (common::trim(line).empty() || common::trim(line)[0] == '#') continue;
		const auto c = splitCsv(line);
		const std::string where = path + ":" + std::to_string(lineNo);
		if (c.size() != 4) throw std::runtime_error(where + ": expected 4 columns, got " + std::to_string(c.size()));
		if (c[1] != "cw" && c[1] != "ccw") throw std::runtime_error(where + ": direction must be cw or ccw, got '" + c[1] + "'");
		calib::TUmbmarkEndpoint e{c[1] == "cw", number(c[2], where) * scale, number(c[3], where) * scale, where};
		if (!table.runs.count(c[0])) table.groups.push_back(c[0]);
		table.runs[c[0]].push_back(e);
	}
	if (table.groups.empty()) throw std::runtime_error(path + ": no end point");
	return table;
}

}  // namespace hslam::apps
