/* hslam: a wide search for the first match after an odometry gap of
 * unknown motion (issue 12, "Recovery": after a gap, search wider before
 * accepting).
 *
 * Without odometry the front-end predicts the motion with a constant
 * velocity, which at the start of a log (or after a stop) is zero and whose
 * uncertainty grows with the gap (CMotionPrior cv_*). ICP converges only
 * within about half a metre and, with its restarts, 15-30 deg of its seed;
 * csail cut at entry 500 starts with a 1.2 m, 36 deg step of unknown motion,
 * and the first match settled 40 deg off (0.9 m error for 7 s, ATE 0.246 m).
 *
 * This search is correlative scan matching with branch-and-bound
 * (graph::CCorrelativeScanMatcher, the loop-closure back-end's matcher) of
 * the scan against the last matched scan, over the constant-velocity
 * prior's window_sigmas-sigma window (capped), when that window is wider
 * than ICP's basin. Its best pose is one more ICP seed; the seeds' fit
 * decides (CScanMatchingPoseEstimator::runIcp), so a search that lands in
 * the wrong place of a symmetric room loses to a prediction that fits
 * better. Both scans are cut at max_range_m so the likelihood field stays
 * small.
 *
 * The same search runs after a poor match with odometry (after_poor_match):
 * odometry's heading errors are heavy-tailed, and a slip of 40-50 deg (csail
 * with noisy readings) leaves ICP and its restarts in a wrong basin near the
 * prediction. Its window is the odometry model's with at least
 * slip_min_yaw_rad of heading, its scans cut at slip_max_range_m. No I/O. */
#pragma once

#include <hslam/graph/CCorrelativeScanMatcher.h>

#include <Eigen/Core>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace hslam::slam
{
struct TGapSearchOptions
{
	bool enabled = true;
	double window_sigmas = 3;  //!< half-width of the window in prior standard deviations
	double max_window_xy_m = 2;  //!< the window's half-width is capped here (m)...
	double max_window_yaw_rad = 60.0 * M_PI / 180.0;  //!< ...and here (rad)
	/** A prior whose window reaches half a turn each way (window_sigmas x its
	 * heading std >= 180 deg) holds no heading: the whole circle is searched,
	 * not max_window_yaw_rad. */
	bool whole_circle_if_heading_unknown = true;
	/** No search when the window is within both (ICP's basin and its restarts cover it). */
	double min_window_xy_m = 0.5;
	double min_window_yaw_rad = 15.0 * M_PI / 180.0;
	double max_range_m = 20;  //!< points farther from the scanner are left out of the search
	double resolution_m = 0.1;  //!< cell of the likelihood field
	double kernel_sigma_m = 0.1;  //!< its blur around each reference point
	double min_score = 0.2;  //!< mean likelihood below which the search gives no seed
	/** ICP from the searched pose replaces the first match only if it fits
	 * the keyframes ([icp] seed_fit_sigma_m) at least this much better. */
	double min_fit_gain = 0.1;
	/** Also search after a poor match with odometry (not good, or fitting
	 * below [icp] restart_below_fit): a heading slip beyond the odometry
	 * model leaves ICP and its restarts in a wrong basin near the
	 * prediction. The window's heading is at least slip_min_yaw_rad; points
	 * beyond slip_max_range_m are left out (fewer rotations to test). */
	bool after_poor_match = true;
	double slip_min_yaw_rad = 45.0 * M_PI / 180.0;
	double slip_max_range_m = 8;
	/** A searched pose this close to the first match is not refined (ICP would end there again). */
	double slip_same_basin_m = 0.25;
	double slip_same_basin_rad = 5.0 * M_PI / 180.0;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.real("window_sigmas", window_sigmas, 0.5, 10.0);
		v.real("max_window_xy_m", max_window_xy_m, 0.0, 20.0);
		v.degrees("max_window_yaw_deg", max_window_yaw_rad, 0.0, 180.0);
		v.flag("whole_circle_if_heading_unknown", whole_circle_if_heading_unknown);
		v.real("min_window_xy_m", min_window_xy_m, 0.0, 20.0);
		v.degrees("min_window_yaw_deg", min_window_yaw_rad, 0.0, 180.0);
		v.real("max_range_m", max_range_m, 1.0, 200.0);
		v.real("resolution_m", resolution_m, 0.01, 1.0);
		v.real("kernel_sigma_m", kernel_sigma_m, 0.005, 1.0);
		v.real("min_score", min_score, 0.0, 1.0);
		v.real("min_fit_gain", min_fit_gain, 0.0, 1.0);
		v.flag("after_poor_match", after_poor_match);
		v.degrees("slip_min_yaw_deg", slip_min_yaw_rad, 0.0, 180.0);
		v.real("slip_max_range_m", slip_max_range_m, 1.0, 200.0);
		v.real("slip_same_basin_m", slip_same_basin_m, 0.0, 10.0);
		v.degrees("slip_same_basin_deg", slip_same_basin_rad, 0.0, 180.0);
	}
};

/** What a search follows: its points are cut at max_range_m or slip_max_range_m. */
enum class ESearchKind
{
	after_gap,
	after_poor_match
};

class CGapSearch
{
   public:
	explicit CGapSearch(const TGapSearchOptions& options = {});
	const TGapSearchOptions& options() const { return m_options; }

	/** The window (half-widths) for a prior of covariance `motionCov`
	 * (x, y, yaw of the motion since the last match); nullopt when it is
	 * within ICP's basin or the search is off. */
	std::optional<graph::TSearchWindow> windowFor(const Eigen::Matrix3d& motionCov) const;
	/** The window after a poor match with odometry: windowFor's, with at
	 * least slip_min_yaw_rad of heading; nullopt when after_poor_match is off. */
	std::optional<graph::TSearchWindow> slipWindowFor(const Eigen::Matrix3d& motionCov) const;

	/** Pose of the current scan (robot-frame points `scan`) relative to the
	 * previous one (robot-frame points `previous`), best in `window` around
	 * `guess` (the predicted relative motion); nullopt if nothing scores
	 * min_score. Not const: each kind of search keeps its matcher (field
	 * buffers and log table) from one search to the next. */
	std::optional<mrpt::poses::CPose2D> search(const mrpt::maps::CSimplePointsMap& previous,
											   const mrpt::maps::CSimplePointsMap& scan, const mrpt::poses::CPose2D& guess,
											   const graph::TSearchWindow& window,
											   ESearchKind kind = ESearchKind::after_gap);

   private:
	/** Half-widths of window_sigmas standard deviations of `motionCov`, capped. */
	graph::TSearchWindow cappedWindow(const Eigen::Matrix3d& motionCov) const;

	/** The matcher's options for one kind of search (the range cut differs). */
	graph::TCorrelativeMatcherOptions matcherOptions(ESearchKind kind) const;

	TGapSearchOptions m_options;
	graph::CCorrelativeScanMatcher m_afterGap, m_afterPoorMatch;
};

}  // namespace hslam::slam
