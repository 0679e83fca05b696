/* hslam nav: sector selecting layer (thesis 4.2.1, figure 61). Looks for clear
 * directions ahead: a direction is clear when a corridor as wide as the robot
 * (plus a margin) is free for clear_distance_mm, or up to the target if that
 * is nearer. It returns the best clear direction on the left and on the right
 * (the one with the longest free corridor; nothing if none), and whether the
 * target's own bearing is clear. The target seeking layer then keeps only the
 * candidate nearest the target bearing (figure 60: it subsumes this layer);
 * in a crowded place with no clear sector the default is straight ahead. */
#pragma once

#include <hslam/nav/CRangeFusion.h>

#include <optional>

namespace hslam::nav
{
struct TSectorSelectingOptions
{
	double clear_distance_mm = 1500;  //!< a sector must be free this far
	double robot_half_width_mm = 260;  //!< P3-DX: 381 mm wide, 455 long; radius of the footprint's disc
	double margin_mm = 80;  //!< clearance added to the half width
	double search_half_angle_rad = 100.0 * M_PI / 180.0;  //!< directions considered each side of ahead
	double step_rad = 4.0 * M_PI / 180.0;  //!< angular step of the search

	template <class V>
	void visit(V& v)
	{
		v.real("clear_distance_mm", clear_distance_mm, 100.0, 10000.0);
		v.real("robot_half_width_mm", robot_half_width_mm, 50.0, 2000.0);
		v.real("margin_mm", margin_mm, 0.0, 1000.0);
		v.degrees("search_half_angle_deg", search_half_angle_rad, 10.0, 180.0);
		v.degrees("step_deg", step_rad, 0.5, 30.0);
	}
};

struct TSectorChoice
{
	std::optional<double> left_rad, right_rad;  //!< best clear heading each side (robot frame)
	bool target_clear = false;  //!< the target bearing itself is clear
	/** The heading the target seeking layer keeps: target bearing if clear, else
	 * the candidate nearest it, else 0 (ahead). */
	double chosen_rad = 0;
	bool any_clear = false;
};

class CSectorSelectingLayer
{
   public:
	explicit CSectorSelectingLayer(const TSectorSelectingOptions& options = {}) : m_opts(options) {}
	TSectorChoice evaluate(const CPolarProfile& profile, double targetBearing_rad, double targetDistance_m) const;

   private:
	TSectorSelectingOptions m_opts;
};

}  // namespace hslam::nav
