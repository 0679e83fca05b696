/* hslam sim: how the simulated robot is driven.
 *
 * CPathFollower: waypoints driven "turn, then go straight" as the UMBmark
 * square of thesis 4.1 is driven (turn in place towards the next waypoint
 * until the heading error is below align_tolerance, then drive with a
 * proportional heading correction, slowing down before the waypoint; if the
 * heading error grows beyond turn_in_place_above, stop and turn again).
 * It is given the pose it should believe (true pose for a perfectly localised
 * robot, odometry for a dead-reckoning run such as UMBmark).
 *
 * CVelocityScript: a list of (duration, v, w) commands played in order. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace hslam::sim
{
struct TVelocityCommand
{
	double v_mps = 0, w_rad_s = 0;
};

struct TPathFollowerOptions
{
	double cruise_speed_mps = 0.4;
	double turn_rate_rad_s = 40.0 * M_PI / 180.0;  //!< in-place turn rate
	double align_tolerance_rad = 0.5 * M_PI / 180.0;  //!< turn in place until the heading error is below
	double turn_in_place_above_rad = 30.0 * M_PI / 180.0;  //!< stop and turn if the error exceeds this
	double heading_gain = 2.0;  //!< w = gain * heading error while driving (1/s)
	double goal_tolerance_m = 0.02;  //!< waypoint reached within this distance
	double slow_down_distance_m = 0.4;  //!< speed ramps down linearly within this distance
	double min_speed_mps = 0.03;

	template <class V>
	void visit(V& v)
	{
		v.real("cruise_speed_mps", cruise_speed_mps, 0.01, 2.0);
		v.degrees("turn_rate_deg_s", turn_rate_rad_s, 1.0, 300.0);
		v.degrees("align_tolerance_deg", align_tolerance_rad, 0.01, 45.0);
		v.degrees("turn_in_place_above_deg", turn_in_place_above_rad, 1.0, 180.0);
		v.real("heading_gain", heading_gain, 0.0, 20.0);
		v.real("goal_tolerance_m", goal_tolerance_m, 0.001, 1.0);
		v.real("slow_down_distance_m", slow_down_distance_m, 0.0, 5.0);
		v.real("min_speed_mps", min_speed_mps, 0.0, 1.0);
	}
};

class CPathFollower
{
   public:
	CPathFollower(const TPathFollowerOptions& options, std::vector<mrpt::math::TPoint2D> waypoints);

	/** Command for the current pose; advances through reached waypoints. */
	TVelocityCommand command(const mrpt::math::TPose2D& pose);
	bool finished() const { return m_next >= m_waypoints.size(); }
	size_t nextWaypoint() const { return m_next; }
	const std::vector<mrpt::math::TPoint2D>& waypoints() const { return m_waypoints; }

   private:
	TPathFollowerOptions m_opts;
	std::vector<mrpt::math::TPoint2D> m_waypoints;
	size_t m_next = 0;
	bool m_turning = true;
};

class CVelocityScript
{
   public:
	struct TSegment
	{
		double duration_s = 0;
		TVelocityCommand command;
	};
	explicit CVelocityScript(std::vector<TSegment> segments);
	/** Command at time t_s since the start (zero after the end). */
	TVelocityCommand commandAt(double t_s) const;
	double duration_s() const { return m_total; }

   private:
	std::vector<TSegment> m_segments;
	double m_total = 0;
};

/** Parses "x y; x y; ..." (m). `what` names the field in errors (std::runtime_error). */
std::vector<mrpt::math::TPoint2D> parseWaypointList(const std::string& text, const std::string& what);
/** Parses "duration_s v_mps w_deg_s; ..." into script segments. */
std::vector<CVelocityScript::TSegment> parseVelocityScript(const std::string& text, const std::string& what);

}  // namespace hslam::sim
