/* hslam nav: sector selecting layer (thesis 4.2.1, figure 61). Looks for clear
 * directions ahead: a direction is clear when a corridor as wide as the robot
 * (plus a margin) is free for clear_distance_mm, or up to the target if that
 * is nearer. It returns the best clear direction on the left and on the right
 * (the one with the longest free corridor; nothing if none), and whether the
 * target's own bearing is clear. The target seeking layer then keeps only the
 * candidate nearest the target bearing (figure 60: it subsumes this layer);
 * in a crowded place with no clear sector the default is straight ahead.
 *
 * Gaps (an addition; thesis figure 61 draws the sectors as the openings
 * between obstacles but its test is a straight corridor from where the robot
 * stands, docs/nav.md): a straight corridor finds a 0.9 m doorway only from
 * near its axis; seen at an angle, its jambs block every corridor through
 * it. So the layer also lists the gaps of the laser's field (+-gap_field_deg):
 * a range discontinuity deeper than the robot's width opens a gap at its near
 * edge E; the other side is the profile point nearest E on the opening's side
 * (the far jamb). A gap is passable when that width is at least the robot's
 * width plus twice the margin. Its heading is a door-passing one: towards
 * the gap's axis (the perpendicular through its middle) at a point
 * approach_gain x the robot's offset from the axis before the gap, and along
 * the axis through the gap once within half the gap's slack of it (pure
 * pursuit with lookahead_mm), so the robot lines up before it enters (also
 * for wide gaps: heading straight at the middle whenever a robot-wide
 * corridor that way was free measured worse, docs/nav.md). When
 * the target is not clear, the target seeking layer keeps the candidate (clear
 * sector or passable gap) with the shortest estimated path to the target, the
 * tangent bug heuristic |P| + |T - P| (Kamon, Rivlin, Rimon 1998) with P the
 * gap's middle or the end of the sector's free corridor; with use_gaps = false
 * it keeps the sector nearest the target bearing, as before. */
#pragma once

#include <hslam/nav/CRangeFusion.h>

#include <optional>
#include <vector>

namespace hslam::nav
{
struct TSectorSelectingOptions
{
	double clear_distance_mm = 1500;  //!< a sector must be free this far
	double robot_half_width_mm = 260;  //!< P3-DX: 381 mm wide, 455 long; radius of the footprint's disc
	double margin_mm = 80;  //!< clearance added to the half width
	double search_half_angle_rad = 180.0 * M_PI / 180.0;  //!< directions considered each side of ahead
	double step_rad = 4.0 * M_PI / 180.0;  //!< angular step of the search
	bool use_gaps = true;  //!< gap candidates and the tangent-bug choice (header)
	double gap_field_rad = 90.0 * M_PI / 180.0;  //!< gaps are looked for within +- this (the laser's field)
	double max_gap_width_mm = 3000;  //!< wider openings are left to the sectors
	double approach_gain = 1.0;  //!< approach point this times the offset from the axis before the gap
	double lookahead_mm = 600;  //!< pure pursuit along the gap's axis

	template <class V>
	void visit(V& v)
	{
		v.real("clear_distance_mm", clear_distance_mm, 100.0, 10000.0);
		v.real("robot_half_width_mm", robot_half_width_mm, 50.0, 2000.0);
		v.real("margin_mm", margin_mm, 0.0, 1000.0);
		v.degrees("search_half_angle_deg", search_half_angle_rad, 10.0, 180.0);
		v.degrees("step_deg", step_rad, 0.5, 30.0);
		v.flag("use_gaps", use_gaps);
		v.degrees("gap_field_deg", gap_field_rad, 10.0, 180.0);
		v.real("max_gap_width_mm", max_gap_width_mm, 100.0, 20000.0);
		v.real("approach_gain", approach_gain, 0.0, 10.0);
		v.real("lookahead_mm", lookahead_mm, 50.0, 5000.0);
	}
};

/** A passable opening between two obstacle points (robot frame, m). */
struct TGap
{
	double ex = 0, ey = 0;  //!< near edge (the discontinuity)
	double qx = 0, qy = 0;  //!< other side (profile point nearest the edge on the opening's side)
	double width_m = 0;
	double heading_rad = 0;  //!< door-passing heading (header)
	double cost_m = 0;  //!< tangent-bug estimate of the path to the target through the gap's middle
};

struct TSectorChoice
{
	std::optional<double> left_rad, right_rad;  //!< best clear heading each side (robot frame)
	bool target_clear = false;  //!< the target bearing itself is clear
	/** The heading the target seeking layer keeps: target bearing if clear, else
	 * the candidate nearest it, else 0 (ahead). */
	double chosen_rad = 0;
	bool any_clear = false;
	std::vector<TGap> gaps;  //!< passable gaps (use_gaps)
	int chosen_gap = -1;  //!< index in gaps when the chosen heading is a gap's
};

class CSectorSelectingLayer
{
   public:
	explicit CSectorSelectingLayer(const TSectorSelectingOptions& options = {}) : m_opts(options) {}
	TSectorChoice evaluate(const CPolarProfile& profile, double targetBearing_rad, double targetDistance_m) const;
	/** Passable gaps of the profile (header), with headings and costs for the target at (tx, ty) (robot frame). */
	void findGaps(const CPolarProfile& profile, double tx, double ty, std::vector<TGap>& gaps) const;
	/** Door-passing heading through the gap E-Q (header). */
	double gapHeading(double ex, double ey, double qx, double qy) const;

   private:
	/** The best clear heading on each side (longest free corridor, then
	 * nearest the target) from the corridor free distances of headings -n..n. */
	void pickClearSides(const std::vector<double>& freeOf, int n, double targetBearing, TSectorChoice& out,
						double& freeLeft, double& freeRight) const;

	TSectorSelectingOptions m_opts;
	mutable std::vector<double> m_freeScratch;  //!< free distance per heading, reused by evaluate()
};

}  // namespace hslam::nav
