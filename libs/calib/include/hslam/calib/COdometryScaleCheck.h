/* hslam calib: detects odometry that reports a gross fraction or multiple of
 * the robot's motion, and rescales it.
 *
 * Why: issue 12's "laser only" log has wheel readings that are nearly
 * constant, not zero. Readings in the wrong units (millimetres read as
 * metres, degrees as radians), a wrong encoder resolution or gear ratio, or
 * a driver that reports a creeping fraction of the motion all look alike: a
 * steady ratio between what the odometry says and what scan matching
 * measures, far from 1. The UKF cannot treat that as noise, the self-
 * calibration (COdometrySelfCalibration) is bounded to +-10 %, and
 * CMotionPrior's stall rule only replaces the readings where the scan
 * shows the disagreement: down a bare corridor, where the scan cannot,
 * the estimate followed the creeping readings (stress matrix 'creep' at a
 * scan per second: long corridor 57.2 m, its odometry's 57.1 m).
 *
 * Model: intervals between two accepted good matches (odometry increment o,
 * matched increment m) are joined until |m| reaches sample_distance_m,
 * a sample log(|o| / |m|) of the distance, and, separately, until |m_phi|
 * reaches sample_turn_deg (within 2 m of travel), a sample
 * log(|o_phi| / |m_phi|) of the turn; a sample whose odometry runs the
 * other way counts as disagreeing. Once min_samples
 * samples are in, if their median departs from 0 by at least
 * log(min_scale_factor), no further than log(max_scale_factor), and at least
 * min_consistent_fraction of the samples lie within a factor
 * consistent_within_factor of it, the quantity is off: its scale (the
 * matched over the odometric motion, summed over the samples that agree) is
 * applied to every later increment once both quantities have min_samples
 * samples, and refined as samples come. Distance and turn are judged
 * separately (a units error may touch only one). Exact zeros are
 * no samples: readings that never move hold no scale (the estimator's
 * laser-only rules handle them). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace hslam::calib
{
struct TOdometryScaleCheck
{
	bool enabled = true;
	int min_samples = 10;  //!< samples of a quantity before it is judged
	double sample_distance_m = 0.2;  //!< matched distance for a distance sample
	double sample_turn_rad = 10.0 * M_PI / 180.0;  //!< matched turn for a turn sample
	double min_scale_factor = 5.0;  //!< |log ratio| at least log of this: a gross error
	double max_scale_factor = 1000.0;  //!< ...and at most log of this (beyond: noise on zeros)
	double consistent_within_factor = 2.0;  //!< a sample agrees within this factor of the median
	double min_consistent_fraction = 0.6;  //!< share of samples that must agree
	/** Apply the scales found (else only report them). */
	bool rescale = true;
	/** Rescaled readings are only as fine as their units: the readings'
	 * finest turn (the smallest non-zero turn of an increment), times the
	 * turn scale, must be at most this, or the scales are only reported.
	 * (The finest distance says nothing: on smooth readings it is the
	 * slowest step driven, not a unit.) */
	double max_rescaled_turn_step_rad = 0.5 * M_PI / 180.0;
	/** Scales known before the run (a known units error, or the batch job's
	 * second pass), applied from the first reading until the check finds its own. */
	double distance_scale = 1.0, turn_scale = 1.0;
	/** The batch job runs the log again from the start with the scales found
	 * (the scans before they were found had already bent the map). */
	bool second_pass = true;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.integer("min_samples", min_samples, 3, 100000);
		v.real("sample_distance_m", sample_distance_m, 0.01, 100.0);
		v.degrees("sample_turn_deg", sample_turn_rad, 1.0, 180.0);
		v.real("min_scale_factor", min_scale_factor, 1.5, 1e6);
		v.real("max_scale_factor", max_scale_factor, 1.5, 1e9);
		v.real("consistent_within_factor", consistent_within_factor, 1.01, 100.0);
		v.real("min_consistent_fraction", min_consistent_fraction, 0.0, 1.0);
		v.flag("rescale", rescale);
		v.degrees("max_rescaled_turn_step_deg", max_rescaled_turn_step_rad, 0.0, 180.0);
		v.real("distance_scale", distance_scale, 1e-9, 1e9);
		v.real("turn_scale", turn_scale, 1e-9, 1e9);
		v.flag("second_pass", second_pass);
	}
};

/** One quantity's samples (distance or turn) and its decision. */
struct TOdometryScaleFit
{
	double scale = 1.0;  //!< applied to the odometry (1 until applied)
	bool applied = false;
	size_t samples = 0;
	double median_ratio = 1.0;  //!< odometry / matched, median of the samples so far
};

class COdometryScaleCheck
{
   public:
	explicit COdometryScaleCheck(const TOdometryScaleCheck& options) : m_opts(options) {}
	const TOdometryScaleCheck& options() const { return m_opts; }

	/** An interval between two accepted good matches: the odometry's
	 * increment as reported and the matched one (robot frame at its start). */
	void observe(const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& matched);
	/** Every known increment as reported (its finest turn: max_rescaled_turn_step_rad). */
	void noteIncrement(const mrpt::poses::CPose2D& increment);
	/** The smallest non-zero turn (rad) of an increment so far (0: none). */
	double turnStep_rad() const { return m_turnStep_rad; }
	/** `increment` with the applied scales (unchanged until one is applied). */
	mrpt::poses::CPose2D correct(const mrpt::poses::CPose2D& increment) const;

	/** Whether the check found a scale that correct() applies with rescale
	 * on: both quantities were judged, and the rescaled readings are fine
	 * enough (the known scales of the options aside). */
	bool applying() const;
	/** The distance (x) and turn (y) scales correct() applies now. */
	mrpt::math::TPoint2D scaleInUse() const;
	const TOdometryScaleFit& distance() const { return m_distance; }
	const TOdometryScaleFit& turn() const { return m_turn; }

   private:
	/** One interval: the odometry's motion (negative where it ran against
	 * the matched motion) and the matched motion (positive). */
	struct TSample
	{
		double odometry = 0, matched = 0;
	};
	/** Adds a sample and judges the quantity again (and refines an applied scale). */
	void addSample(TOdometryScaleFit& fit, std::vector<TSample>& samples, double odometry, double matched);

	/** Intervals joined since the last sample of a quantity. */
	struct TJoined
	{
		mrpt::poses::CPose2D odometry, matched;
	};
	static constexpr double kMaxTurnSampleTravel_m = 2.0;

	TOdometryScaleCheck m_opts;
	TJoined m_forDistance, m_forTurn;
	double m_turnStep_rad = 0;
	TOdometryScaleFit m_distance, m_turn;
	std::vector<TSample> m_distanceSamples, m_turnSamples;
};

}  // namespace hslam::calib
