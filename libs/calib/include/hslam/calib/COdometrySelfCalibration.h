/* hslam calib: estimates the odometry's systematic errors online, from the
 * pose estimator's own results, and corrects the increments it is fed.
 *
 * Why: the UKF (thesis 4.5) treats odometry errors as zero-mean noise, but a
 * real robot's odometry is biased: a mean wheel diameter unlike the nominal
 * one (Borenstein's scaling error Es) or unequal wheels and a wrong wheelbase
 * (UMBmark's Ed and Eb, thesis 4.1). Where scan matching constrains the
 * motion only weakly (corridors, clutter) the fused estimate follows the
 * prediction, so a biased odometry leaks into the trajectory: on intel the
 * odometry overstates distance by 5 % and the fused steps kept 1.6 % of it,
 * a map 1.1 % too large (docs/pose-estimation.md, "Odometry self-calibration").
 *
 * Model, per interval between two accepted matches (odometry increment o,
 * fused increment m, both in the robot frame at the interval's start):
 *     distance   |m| = a |o|                       (a = Es for the distance)
 *     heading    m_phi = b o_phi + c s_o           (b = 1/Eb, c from Ed)
 * fitted by weighted least squares, each interval weighted by 1 / its wheel
 * travel (odometry error is a random walk in the travelled distance), with
 * the nominal calibration (a = b = 1, c = 0) as a prior worth
 * `prior_travel_m` of travel. The fit is turned into UMBmark factors
 * (c_L, c_R, Eb of eq. 25-28) and applied with COdometryCorrection.
 *
 * The fused increments lean towards the corrected odometry: where the
 * matches fix only a fraction w of the distance travelled (w < 1 along a
 * corridor's axis), an interval says |m| = (w s + (1 - w) a) |o| for a true
 * scale s and the scale a applied at the time. Its fixed point is s, but a
 * fit over the whole run averages the early intervals, driven at the
 * nominal scale, with the later ones, and stops short: on the simulated
 * floor with 5 % long odometry it ended at 0.970 for a true 0.950 (ATE
 * 0.45 m). Optionally (`rebase_travel_m` > 0), once applied, the fit is
 * re-based every so much travel: the scale reached becomes the base and the
 * sums restart on odometry corrected by it, so each stretch moves the scale
 * a further fraction w of the way (the same floor, every 20 m: 0.951 at the
 * end, but ATE only 0.45 -> 0.39 m, the early part having run at the wrong
 * scale). Off by default: over twenty starts per real log it did not
 * improve both logs it acts on (docs/pose-estimation.md, "Odometry
 * self-calibration"). */
#pragma once

#include <hslam/calib/COdometryCorrection.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>

namespace hslam::calib
{
struct TOdometrySelfCalibration
{
	bool enabled = true;
	bool estimate_heading = true;  //!< also fit b and c (UMBmark heading terms); see the INI and docs
	double prior_travel_m = 10.0;  //!< weight of the nominal calibration, in metres of travel
	double max_scale_error = 0.1;  //!< factors stay within 1 +- this (TOdometryCorrection's range)
	/** The correction is applied only once the fitted distance scale has
	 * departed from nominal by more than this (and stays applied after).
	 * The front-end has a distance bias of its own (point ICP sticks to its
	 * seed along walls): on the simulated samples, whose odometry is exact,
	 * the fit stays within 0.56 % of 1 while nothing is applied, but once
	 * applied it feeds back to 0.987-0.993 and makes them worse; the fit
	 * cannot tell an odometry error that small from that bias. */
	double min_scale_error = 0.01;
	/** ...and by more than this many of its standard errors (from the fit's
	 * residuals): early in a run the front-end's own distance bias (a far-
	 * reaching scanner's grazing points) can look like an odometry error. */
	double min_scale_significance = 0.0;
	/** estimate_heading: the heading terms are applied only once the fitted
	 * heading scale has left 1 +- min_heading_scale_error or the curvature
	 * exceeds min_curvature_rad_per_m (and stay applied after). */
	double min_heading_scale_error = 0.01;
	double min_curvature_rad_per_m = 0.5 * M_PI / 180.0;
	/** The heading terms must also depart from nominal by more than this
	 * many of their standard errors (from the fit's residuals): early in a
	 * run, with noisy odometry, a few intervals fit a curvature that is not
	 * there. */
	double min_heading_significance = 1.0;
	double max_interval_m = 2.0;  //!< longer intervals (after failed matches) are not used
	double max_distance_residual = 0.25;  //!< |m| - a|o| beyond this fraction of |o| (+ 2 cm): outlier
	double max_heading_residual_rad = 5.0 * M_PI / 180.0;  //!< heading disagreement beyond this: outlier
	/** Once applied, the distance fit restarts from the scale reached after
	 * this much odometric travel (m); 0 = one fit over the whole run. */
	double rebase_travel_m = 0.0;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.flag("estimate_heading", estimate_heading);
		v.real("prior_travel_m", prior_travel_m, 0.1, 1e6);
		v.real("max_scale_error", max_scale_error, 0.0, 0.1);
		v.real("min_scale_error", min_scale_error, 0.0, 0.1);
		v.real("min_heading_scale_error", min_heading_scale_error, 0.0, 0.1);
		v.degrees("min_curvature_deg_per_m", min_curvature_rad_per_m, 0.0, 45.0);
		v.real("min_heading_significance", min_heading_significance, 0.0, 100.0);
		v.real("min_scale_significance", min_scale_significance, 0.0, 100.0);
		v.real("max_interval_m", max_interval_m, 0.05, 100.0);
		v.real("max_distance_residual", max_distance_residual, 0.01, 10.0);
		v.degrees("max_heading_residual_deg", max_heading_residual_rad, 0.1, 180.0);
		v.real("rebase_travel_m", rebase_travel_m, 0.0, 1e6);
	}
};

/** What the fit says, in the model's terms and as UMBmark factors. */
struct TOdometrySelfCalibrationState
{
	double distance_scale = 1.0;  //!< a: matched / odometric distance
	double heading_scale = 1.0;  //!< b: matched / odometric heading change (1 / Eb)
	double curvature_bias_rad_per_m = 0.0;  //!< c: heading gained per metre driven (Ed)
	double travel_m = 0.0;  //!< odometric distance of the intervals used
	size_t intervals = 0, outliers = 0;
	size_t rebases = 0;  //!< times the distance fit restarted from the scale reached
	/** The heading terms (b, c) are part of `correction`: estimate_heading,
	 * and the fit has left the band of min_heading_* (and stays applied). */
	bool heading_applied = false;
	/** The distance scale is part of `correction`: it has left 1 +-
	 * min_scale_error by min_scale_significance standard errors (and stays
	 * applied). */
	bool distance_applied = false;
	/** The applied parts as c_L, c_R, Eb; enabled once either part is. */
	TOdometryCorrection correction;
};

class COdometrySelfCalibration
{
   public:
	/** `nominalWheelbase_m` only converts the fit to UMBmark factors. */
	COdometrySelfCalibration(const TOdometrySelfCalibration& options, double nominalWheelbase_m);

	bool enabled() const { return m_opts.enabled; }
	const TOdometrySelfCalibration& options() const { return m_opts; }
	const TOdometrySelfCalibrationState& state() const { return m_state; }

	/** `odometry` corrected with the current fit (unchanged when disabled). */
	mrpt::poses::CPose2D correct(const mrpt::poses::CPose2D& odometry) const;

	/** One interval between accepted matches: the uncorrected odometry
	 * increment and the estimator's fused increment over the same time. */
	void observe(const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& fused);

   private:
	void refit();
	/** The heading terms b and c (when estimate_heading), and whether they
	 * are now applied. */
	void fitHeading();
	/** Standard error of the distance scale, from the fit's residuals. */
	double distanceScaleError() const;

	TOdometrySelfCalibration m_opts;
	double m_wheelbase_m = 0.335;
	void rebaseIfDue();

	// Weighted sums of the distance fit (odometry scaled by m_baseScale) and
	// of the 2x2 heading fit.
	double m_baseScale = 1.0, m_travelSinceRebase_m = 0.0;
	double m_sumMatchedDistance = 0, m_sumOdometryDistance = 0, m_sumMatchedSquared = 0;
	size_t m_intervalsSinceRebase = 0;
	double m_hh = 0, m_hs = 0, m_ss = 0, m_hy = 0, m_sy = 0, m_yy = 0;
	TOdometrySelfCalibrationState m_state;
};

}  // namespace hslam::calib
