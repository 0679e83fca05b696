/* hslam sim: a walking person seen at laser height as a pair of legs
 * (thesis 4.7: legs are what a scan at ~0.3 m height sees of a person).
 *
 * The body moves along a polyline of waypoints at constant speed v (looping
 * back to the first waypoint, or walking back and forth). The legs follow a
 * gait with alternating stance and swing phases: feet are placed every
 * step_length_m along the path, alternately left and right of it
 * (hip_half_width_m). In each half-cycle (duration step_length/v) one leg
 * stands still on its footprint while the other swings from behind the body
 * to ahead of it at 2v, so the mean of the two legs is always the body
 * position. Leg cylinders have radius leg_radius_m (5-8 cm for a human). */
#pragma once

#include <hslam/sim/world.h>
#include <mrpt/math/TPoint2D.h>

#include <array>
#include <vector>

namespace hslam::sim
{
struct TPersonSpec
{
	int id = 0;
	double speed_mps = 1.0;  //!< walking speed along the path (human: 0.5-1.5 m/s)
	double leg_radius_m = 0.06;
	double step_length_m = 0.6;  //!< distance between consecutive footprints along the path
	double hip_half_width_m = 0.1;  //!< lateral offset of each leg from the path
	double start_delay_s = 0;  //!< stands at the first waypoint until this time
	bool loop = true;  //!< true: closed loop back to the first waypoint; false: back and forth
	std::vector<mrpt::math::TPoint2D> waypoints;  //!< at least 2
};

struct TPersonState
{
	int id = 0;
	mrpt::math::TPoint2D body;  //!< body (path) position, m
	double heading_rad = 0;
	std::array<mrpt::math::TPoint2D, 2> legs;  //!< leg centres, m
	std::array<bool, 2> stance{{true, true}};  //!< true = leg on the ground (not moving)
};

class CWalkingPerson
{
   public:
	/** Throws std::invalid_argument for fewer than 2 waypoints or non-positive sizes. */
	explicit CWalkingPerson(TPersonSpec spec);

	/** State at time t_s (seconds since the simulation start); a pure function of t. */
	TPersonState stateAt(double t_s) const;
	/** The two leg cylinders at time t_s, tagged person_leg/id/leg index. */
	std::vector<TCircle> legCirclesAt(double t_s) const;

	const TPersonSpec& spec() const { return m_spec; }
	double pathLength() const { return m_length; }

   private:
	/** Point and unit tangent at arc length s along the (unfolded) path. */
	void pointAt(double s, mrpt::math::TPoint2D& p, mrpt::math::TVector2D& tangent) const;

	TPersonSpec m_spec;
	std::vector<mrpt::math::TPoint2D> m_path;  //!< closed or mirrored polyline
	std::vector<double> m_cumulative;  //!< arc length at each vertex of m_path
	double m_length = 0;  //!< length of one period of the path
};

}  // namespace hslam::sim
