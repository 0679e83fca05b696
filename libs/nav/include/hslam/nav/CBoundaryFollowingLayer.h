/* hslam nav: boundary following out of local minima (not in the thesis; its
 * 4.2.2 names the reactive controller's drawback, and a U-shaped obstacle
 * facing the target traps it for good). A progress monitor watches the
 * distance to the target; when it has not improved by progress_mm for
 * stuck_time_s the layer takes over the heading (the forward turning layer
 * still subsumes it) and follows the obstacle boundary, keeping it at
 * follow_distance_mm on the side where it is nearer, until the robot is
 * leave_margin_mm closer to the target than where it started following and
 * the target bearing is clear (the leave rule of Lumelsky's Bug algorithms),
 * or max_follow_s has passed. */
#pragma once

#include <hslam/nav/CRangeFusion.h>

namespace hslam::nav
{
struct TBoundaryFollowingOptions
{
	bool enabled = true;
	double stuck_time_s = 15;
	double progress_mm = 300;
	double follow_distance_mm = 650;
	double speed_mm_s = 200;
	double leave_margin_mm = 300;
	double max_follow_s = 120;
	double turn_rate_rad_s = 35.0 * M_PI / 180.0;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.real("stuck_time_s", stuck_time_s, 1.0, 600.0);
		v.real("progress_mm", progress_mm, 10.0, 5000.0);
		v.real("follow_distance_mm", follow_distance_mm, 200.0, 3000.0);
		v.real("speed_mm_s", speed_mm_s, 10.0, 1000.0);
		v.real("leave_margin_mm", leave_margin_mm, 0.0, 5000.0);
		v.real("max_follow_s", max_follow_s, 1.0, 3600.0);
		v.degrees("turn_rate_deg_s", turn_rate_rad_s, 1.0, 300.0);
	}
};

struct TBoundaryFollowingOutput
{
	bool active = false;
	double v_mps = 0, w_rad_s = 0;
};

class CBoundaryFollowingLayer
{
   public:
	explicit CBoundaryFollowingLayer(const TBoundaryFollowingOptions& options = {}) : m_opts(options) {}
	/** targetClear: the sector layer found the target bearing clear. */
	TBoundaryFollowingOutput update(const CPolarProfile& profile, double targetDistance_m, bool targetClear, double t_s);
	/** A new target: forget the progress history. */
	void reset() { m_started = false, m_following = false; }

   private:
	TBoundaryFollowingOutput follow(const CPolarProfile& profile) const;
	TBoundaryFollowingOptions m_opts;
	bool m_started = false, m_following = false;
	double m_best_m = 0, m_lastProgress_s = 0, m_enter_m = 0, m_enter_s = 0;
	double m_side = 1;  //!< +1: boundary on the left, -1: on the right
};

}  // namespace hslam::nav
