/* hslam nav: forward turning layer (thesis 4.2.1, figure 63, eq. 35-36;
 * Appendix A layers 1-2 and the resolver).
 *  - Obstacle ahead nearer than front_trigger_mm (appendix: sonar reading over
 *    +-50 deg minus 300 below 200, i.e. 500 mm from the centre) or a confirmed
 *    corner trap: it subsumes every other layer, backing off at
 *    back_speed_mm_s while rotating at escape_rate_deg_s (towards the more open
 *    side, kept for the whole manoeuvre) until it has rotated escape_angle_deg
 *    (35) or backed escape_distance_mm (150), measured from odometry.
 *  - Otherwise it subsumes the rotational layers partially, with the weights
 *    w_s = 0.5 (1 + tanh(3R/1000 - 9)) (eq. 35) and
 *    w_a = (160 - sqrt(R)) / 160 (eq. 36, printed as w_s; R in mm = range to
 *    the nearest obstacle).
 *  - It also stops the forward motion (subsumes v with 0) while the heading
 *    error is beyond turn_in_place_above_deg: the turn radius needed is beyond
 *    what the robot can do while moving. */
#pragma once

#include <hslam/nav/CCornerTrapDetector.h>
#include <mrpt/math/TPose2D.h>

namespace hslam::nav
{
struct TForwardTurningOptions
{
	double front_trigger_mm = 500;
	double front_half_angle_rad = 50.0 * M_PI / 180.0;
	double back_speed_mm_s = 50;
	double escape_rate_rad_s = 20.0 * M_PI / 180.0;  //!< appendix A: setRotVel(20)
	double escape_angle_rad = 35.0 * M_PI / 180.0;
	double escape_distance_mm = 150;
	double turn_in_place_above_rad = 70.0 * M_PI / 180.0;
	double max_escape_s = 6.0;  //!< safety bound on one manoeuvre

	template <class V>
	void visit(V& v)
	{
		v.real("front_trigger_mm", front_trigger_mm, 100.0, 3000.0);
		v.degrees("front_half_angle_deg", front_half_angle_rad, 5.0, 90.0);
		v.real("back_speed_mm_s", back_speed_mm_s, 0.0, 500.0);
		v.degrees("escape_rate_deg_s", escape_rate_rad_s, 1.0, 300.0);
		v.degrees("escape_angle_deg", escape_angle_rad, 1.0, 180.0);
		v.real("escape_distance_mm", escape_distance_mm, 0.0, 2000.0);
		v.degrees("turn_in_place_above_deg", turn_in_place_above_rad, 5.0, 180.0);
		v.real("max_escape_s", max_escape_s, 0.5, 60.0);
	}
};

/** Eq. 35: weight of the sector (obstacle) heading vs the free target bearing. */
double farRangeWeight(double nearest_mm);
/** Eq. 36: weight of the side avoidance layer. */
double sideAvoidanceWeight(double nearest_mm);

struct TForwardTurningOutput
{
	bool escaping = false;  //!< full subsumption: (v, w) below are the command
	double v_mps = 0, w_rad_s = 0;
	bool corner = false;  //!< the manoeuvre was started by the corner detector
};

class CForwardTurningLayer
{
   public:
	CForwardTurningLayer(const TForwardTurningOptions& options = {}, const TCornerTrapOptions& corner = {})
		: m_opts(options), m_corner(corner)
	{
	}
	/** Starts, continues or ends the back-off manoeuvre. */
	TForwardTurningOutput update(const CPolarProfile& profile, const mrpt::math::TPose2D& pose, double t_s);
	/** Whether a forward speed is allowed for this heading error. */
	bool allowsForwardMotion(double headingError_rad) const
	{
		return std::abs(headingError_rad) <= m_opts.turn_in_place_above_rad;
	}
	const TForwardTurningOptions& options() const { return m_opts; }

   private:
	TForwardTurningOptions m_opts;
	CCornerTrapDetector m_corner;
	bool m_active = false, m_byCorner = false;
	double m_direction = 1;  //!< +1 CCW, -1 CW
	mrpt::math::TPose2D m_start;
	double m_start_s = 0;
};

}  // namespace hslam::nav
