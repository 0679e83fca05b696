/* hslam calib: the time offset between odometry and laser, estimated from
 * what scan matching saw ([odometry_timing] estimate_offset).
 *
 * Odometry stamped late by tau reports at stamp s the pose of time s - tau:
 * the robot's heading change between two matched scans at t1 and t2 is then
 * what the odometry reports between stamps t1 + tau and t2 + tau. For every
 * candidate tau on a grid (offset_step_s over +-max_offset_s) the squared
 * difference between the matched and that odometry heading change is summed
 * over pairs of consecutive good matches (at most max_pair_s apart; each
 * residual capped at residual_cap_deg: a slip does not decide the offset),
 * and the best candidate (parabola-refined) is the estimate. Only heading is
 * used: matching measures it well wherever it measures anything, and a late
 * clock shows most at turns. A pair is scored once odometry up to
 * t2 + max_offset_s has been read.
 *
 * The matched headings are the fused estimate's, which lean towards the
 * odometry the estimator was given (offset applied): the fit is pulled
 * towards the offset in use and is re-applied as it moves. */
#pragma once

#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <optional>
#include <vector>

namespace hslam::calib
{
struct TOdometryTimeOffsetOptions
{
	bool estimate_offset = true;  //!< estimate the offset and apply it once confident
	double max_offset_s = 0.5;  //!< candidates within +- this (s)
	double offset_step_s = 0.01;  //!< grid step of the candidates (s)
	double max_pair_s = 3.0;  //!< longest time between two matches of a pair (s)
	double residual_cap_rad = 5.0 * M_PI / 180.0;  //!< robust cap of one pair's heading residual
	/** Matched rotation summed over scored pairs before the estimate is used (rad). */
	double min_rotation_rad = 0.5 * M_PI;
	/** Applied only when its cost is at most this fraction of the cost of
	 * the offset in use (a clear minimum). Heavy wheel slip under a driver
	 * that steers by the true pose fits a lag that is not there: the
	 * odometry holds the steering's answers to slip it never saw, which
	 * come later (ten times the samples' odometry noise: -0.1 to -0.5 s at
	 * 0.70-0.80 of the cost of 0; a real 0.3 s lag reaches 0.41). */
	double max_cost_ratio = 0.5;
	double min_change_s = 0.02;  //!< smaller changes of the applied offset are not made
	/** Odometry readings per matched pair's interval, on average, below which
	 * nothing is applied: with one reading per scan (the CARMEN imports) a
	 * shift only blends neighbouring steps, and csail's heavy-tailed steps
	 * (-20 then +21 deg) fitted -0.2 s and ran 5.99 m from one start. */
	double min_readings_per_pair = 1.5;

	template <class V>
	void visit(V& v)
	{
		v.flag("estimate_offset", estimate_offset);
		v.real("max_offset_s", max_offset_s, 0.0, 5.0);
		v.real("offset_step_s", offset_step_s, 0.001, 1.0);
		v.real("max_pair_s", max_pair_s, 0.01, 60.0);
		v.degrees("residual_cap_deg", residual_cap_rad, 0.1, 90.0);
		v.degrees("min_rotation_deg", min_rotation_rad, 0.0, 1e6);
		v.real("max_cost_ratio", max_cost_ratio, 0.0, 1.0);
		v.real("min_change_s", min_change_s, 0.0, 5.0);
		v.real("min_readings_per_pair", min_readings_per_pair, 0.0, 1000.0);
	}
};

class COdometryTimeOffset
{
   public:
	explicit COdometryTimeOffset(const TOdometryTimeOffsetOptions& options);

	/** An absolute odometry reading as it was stamped (s), uncorrected. */
	void addReading(double stamp_s, const mrpt::poses::CPose2D& pose);
	/** The estimated heading (rad) at a scan of time t_s whose match was good
	 * and accepted; other scans break the chain of pairs (call breakChain()). */
	void addMatchedHeading(double t_s, double heading_rad);
	void breakChain() { m_lastMatch.reset(); }

	/** Best offset so far (s), with its cost relative to `inUse_s`'s. */
	struct TEstimate
	{
		double offset_s = 0;
		double cost_ratio = 1;  //!< cost(offset) / cost(in use)
		double rotation_rad = 0;  //!< matched rotation behind it
		size_t pairs = 0;
		double readings_per_pair = 0;  //!< mean pair interval / mean reading interval
	};
	std::optional<TEstimate> estimate(double inUse_s) const;
	/** The offset to apply instead of `inUse_s`, if the estimate is confident
	 * and differs by at least min_change_s. */
	std::optional<double> offsetToApply(double inUse_s) const;

   private:
	struct TPair
	{
		double t1_s, t2_s, matchedTurn_rad;
	};
	std::optional<double> odometryHeadingAt(double stamp_s) const;
	void scoreReadyPairs();
	double costAt(double offset_s) const;  //!< interpolated between grid candidates

	TOdometryTimeOffsetOptions m_options;
	std::deque<std::pair<double, double>> m_readings;  //!< (stamp, unwrapped heading)
	std::optional<std::pair<double, double>> m_lastMatch;  //!< (time, heading)
	std::deque<TPair> m_waiting;  //!< pairs waiting for odometry past t2 + max_offset_s
	std::vector<double> m_cost;  //!< per candidate
	std::vector<double> m_residual2;  //!< scratch of scoreReadyPairs(): one pair's residuals per candidate
	double m_rotation_rad = 0;
	size_t m_pairs = 0;
	double m_pairSpan_s = 0;  //!< summed intervals of the scored pairs
	size_t m_readingCount = 0;
	double m_firstReading_s = 0, m_lastReading_s = 0;
};

}  // namespace hslam::calib
