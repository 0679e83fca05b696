/* hslam sim: CPathFollower and CVelocityScript. */
#include <hslam/common/parse_number.h>
#include <hslam/sim/CPathFollower.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hslam::sim
{
CPathFollower::CPathFollower(const TPathFollowerOptions& options, std::vector<mrpt::math::TPoint2D> waypoints)
	: m_opts(options), m_waypoints(std::move(waypoints))
{
}

TVelocityCommand CPathFollower::command(const mrpt::math::TPose2D& pose)
{
	while (m_next < m_waypoints.size())
	{
		const auto& g = m_waypoints[m_next];
		const double dist = std::hypot(g.x - pose.x, g.y - pose.y);
		if (dist > m_opts.goal_tolerance_m)
		{
			// Passed the waypoint while driving (it lies behind): it counts as reached.
			const double along = std::cos(pose.phi) * (g.x - pose.x) + std::sin(pose.phi) * (g.y - pose.y);
			if (!(m_turning == false && along < 0 && dist < 4 * m_opts.goal_tolerance_m)) break;
		}
		++m_next;
		m_turning = true;
	}
	if (finished()) return {};
	const auto& g = m_waypoints[m_next];
	const double dist = std::hypot(g.x - pose.x, g.y - pose.y);
	const double err = mrpt::math::wrapToPi(std::atan2(g.y - pose.y, g.x - pose.x) - pose.phi);
	if (!m_turning && std::abs(err) > m_opts.turn_in_place_above_rad) m_turning = true;
	if (m_turning)
	{
		if (std::abs(err) <= m_opts.align_tolerance_rad)
			m_turning = false;
		else
		{
			// Proportional near the goal heading so the turn ends within tolerance.
			const double w = std::clamp(3.0 * err, -m_opts.turn_rate_rad_s, m_opts.turn_rate_rad_s);
			const double minW = 2.0 * M_PI / 180.0;
			return TVelocityCommand{0.0, std::abs(w) < minW ? std::copysign(minW, err) : w};
		}
	}
	double v = m_opts.cruise_speed_mps;
	if (m_opts.slow_down_distance_m > 0)
		v = std::max(m_opts.min_speed_mps, v * std::min(1.0, dist / m_opts.slow_down_distance_m));
	return TVelocityCommand{v, m_opts.heading_gain * err};
}

CVelocityScript::CVelocityScript(std::vector<TSegment> segments) : m_segments(std::move(segments))
{
	for (const auto& s : m_segments) m_total += s.duration_s;
}

TVelocityCommand CVelocityScript::commandAt(double t) const
{
	for (const auto& s : m_segments)
	{
		if (t < s.duration_s) return s.command;
		t -= s.duration_s;
	}
	return {};
}

namespace
{
std::vector<std::vector<double>> parseGroups(const std::string& text, const std::string& what, size_t perGroup)
{
	std::vector<std::vector<double>> groups;
	std::stringstream ss(text);
	std::string item;
	int index = 0;
	while (std::getline(ss, item, ';'))
	{
		++index;
		std::istringstream is(item);
		std::vector<double> nums;
		std::string tok;
		while (is >> tok)
		{
			const auto v = hslam::common::tryParseDouble(tok);
			if (!v)
				throw std::runtime_error(what + ": item " + std::to_string(index) + ": '" + tok + "' is not a number");
			nums.push_back(*v);
		}
		if (nums.empty()) continue;
		if (nums.size() != perGroup)
			throw std::runtime_error(what + ": item " + std::to_string(index) + " has " + std::to_string(nums.size()) +
									 " numbers, expected " + std::to_string(perGroup));
		groups.push_back(nums);
	}
	return groups;
}
}  // namespace

std::vector<mrpt::math::TPoint2D> parseWaypointList(const std::string& text, const std::string& what)
{
	std::vector<mrpt::math::TPoint2D> pts;
	for (const auto& g : parseGroups(text, what, 2)) pts.push_back(mrpt::math::TPoint2D{g[0], g[1]});
	return pts;
}

std::vector<CVelocityScript::TSegment> parseVelocityScript(const std::string& text, const std::string& what)
{
	std::vector<CVelocityScript::TSegment> segs;
	for (const auto& g : parseGroups(text, what, 3))
	{
		if (!(g[0] >= 0)) throw std::runtime_error(what + ": negative duration");
		segs.push_back(CVelocityScript::TSegment{g[0], TVelocityCommand{g[1], g[2] * M_PI / 180.0}});
	}
	return segs;
}

}  // namespace hslam::sim
