/* hslam: the pose-estimation seam of the pipeline (thesis figure 55: odometry
 * and scan matching fused in a UKF). `[pose_estimation] method` selects the
 * implementation:
 *   odometry    dead reckoning (thesis 4.6.4, before the UKF was switched on)
 *   lines       thesis 4.4-4.5: line-feature scan matching + UKF
 *   icp         MRPT ICP against recent keyframes + UKF
 *   lines+icp   line matching, refined by ICP when weak (thesis future work 5.2)
 * (see CScanMatchingPoseEstimator.h). */
#pragma once

#include <hslam/common/CStageTimer.h>
#include <hslam/common/range_data.h>
#include <hslam/features/line_segment.h>
#include <hslam/matching/match_result.h>
#include <hslam/slam/COdometryTracker.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <string>

namespace hslam::slam
{
/** What an estimator reports for one scan. */
struct TPoseEstimate
{
	mrpt::poses::CPose2D pose;  //!< robot pose in the world frame
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  //!< of (x, y, theta); zero if not tracked
	bool matched = false;  //!< a scan match ran at this scan
	std::string match_method;  //!< which matcher produced the fused result ("lines", "icp", ...)
	matching::EMatchQuality match_quality = matching::EMatchQuality::failed;
	bool match_accepted = false;  //!< the UKF fused it (not rejected by the gate)
	double match_nis = 0;  //!< normalised innovation squared of the fused match
	features::TLineSegmentList lines;  //!< lines extracted from this scan (robot frame), if any
	std::string motion_prior;  //!< why the prior was not odometry ("gap", "frozen", "zeros", "stalled", "jump"), else ""
	long keyframe_id = -1;  //!< id in the estimator's keyframe store if this scan became a keyframe
};

class CPoseEstimator
{
   public:
	virtual ~CPoseEstimator() = default;
	virtual std::string name() const = 0;
	/** Robot pose (world frame) at the time of `scan`, given the odometry
	 * increment since the previous scan; beams flagged in `excludedBeams`
	 * (people, predicted by the dynamic filter) are not matched. */
	virtual TPoseEstimate update(const TOdometryIncrement& increment, const common::TRangeData& scan,
								 const std::vector<bool>* excludedBeams) = 0;
	/** Writes the effective values of the estimator's own INI sections. */
	virtual void saveOptions(mrpt::config::CConfigFileBase& /*out*/) const {}
};

struct TPoseEstimationOptions
{
	std::string method = "lines+icp";  //!< "odometry", "lines", "icp" or "lines+icp" (default: best on the real logs)
	double match_every_m = 0.1;  //!< run the matcher after this much travel (thesis 4.5.3: 0.1 m)...
	double match_every_rad = 5.0 * M_PI / 180.0;  //!< ...or this much rotation (thesis: 5 deg)
	/** ICP against the keyframe map runs at most this often (icp and
	 * lines+icp): each match against a map built from the estimates carries a
	 * small bias along weakly constrained directions, and matching every
	 * 0.1 m accumulated it (simulated 40 m corridor: ATE 1.1 m at 0.1 m,
	 * 0.25 m at 0.5 m; odometry 0.83 m). */
	double icp_every_m = 0.5;
	double icp_every_rad = 10.0 * M_PI / 180.0;
	bool icp_always = true;  //!< lines+icp: ICP at every ICP step (false: only when the line match is weak/failed)
	/** Match at least this often in time (s) even when odometry reports no
	 * travel: wheel readings that stopped or creep (a "laser only" log) are
	 * only noticed when a match finds the motion odometry missed (issue 12).
	 * 0 = never by time. */
	double match_every_s = 0.5;
	/** A timed match after odometry reported less travel than this since
	 * the last ICP checks a standstill claim ([icp] standstill_*). */
	double standstill_max_m = 0.01;
	double standstill_max_rad = 0.5 * M_PI / 180.0;
	/** While odometry counts as stalled ([motion_prior]: readings that
	 * creep), ICP is refined and judged as a standstill check is ([icp]
	 * standstill_*): the constant-velocity prior is no measurement, and
	 * point-to-point ICP pins the estimate where the scan's wall samples fall
	 * on the last keyframe's. */
	bool stalled_point_to_line = true;
	/** While odometry counts as stalled, a translation direction holding
	 * less than this share of the scan's own surface information
	 * (matching::scanTranslationConstraint, normals fitted along the scan
	 * over stalled_normal_radius_m) is left to the constant-velocity prior:
	 * the ICP match's variance there is made huge. 0 = off. */
	double stalled_unconstrained_max_fraction = 0.01;
	double stalled_normal_radius_m = 0.2;
	/** The same in a log without odometry (readings that never moved,
	 * counted frozen), not only while readings are stalled; lost readings
	 * are unconstrained_axis_after_gap's. */
	bool unconstrained_axis_without_odometry = true;
	/** The same after lost readings (not zeros) until the next match, once
	 * a velocity was measured from the estimates (CMotionPrior::velocityKnown;
	 * not at a log's first scans). */
	bool unconstrained_axis_after_gap = true;
	/** The same after readings that froze after motion
	 * (TMotionPrior::froze_after_motion: not a log's first readings at
	 * rest, not the steps of readings that creep), until the next match,
	 * once a velocity was measured: the long corridor at a scan per second
	 * with readings frozen for 10 s stood through the fault as with lost
	 * readings. */
	bool unconstrained_axis_after_freeze = true;
	/** While odometry counts as stalled, an ICP keyframe is also added when
	 * this long (s) has passed since the last one (0 = by travel only). */
	double stalled_keyframe_every_s = 1.0;
	/** icp and lines+icp with point ICP: a keyframe of the ICP reference is
	 * added only at a scan whose own ICP match the filter fused, and a
	 * keyframe due runs ICP (the first keyframe and a stall's timed ones
	 * excepted). A pose carried there by
	 * odometry and frame-to-frame line matches brings their drift into the
	 * map, and later matches against the map then agree with it. */
	bool keyframes_after_icp_only = true;
	/** ...but once the estimate is this many keyframe spacings ([icp_map]
	 * insertion_distance_m / insertion_angle_deg) from the newest keyframe
	 * without an ICP placement, a scan of at least [icp] min_good_points
	 * points is added at the estimate: the reference must not stop at the
	 * first keyframe when ICP fails for a while. */
	double keyframe_without_icp_spacings = 2.0;
	/** icp and lines+icp: "mrpt" = MRPT's point-to-point ICP against the
	 * points of recent keyframes ([icp], [icp_map]); "point_to_line" =
	 * CPointToLineIcp against the local map of the keyframe store
	 * ([keyframes], [map_matching]); "mrpt+point_to_line" = MRPT's result
	 * refined by CPointToLineIcp (MRPT's basin, no sliding along walls). */
	std::string icp_matcher = "mrpt";
	/** icp and lines+icp: also seed ICP where the last well-constrained match
	 * the filter refused puts the robot now (CMotionPrior::
	 * contradictedMatchSeed; the fit, [icp] seed_fit_sigma_m, decides), and
	 * restart the filter there once the refusals declare a stall. */
	bool seed_refused_matches = true;
	/** icp and lines+icp: while the motion since the last match is not
	 * odometry's (readings lost, frozen, jumping or stalled: a constant
	 * velocity stands in, CMotionPrior), also seed ICP at the pose of the
	 * last match: the robot may have stopped or turned where the constant
	 * velocity carries it on. The fit ([icp] seed_fit_sigma_m) decides. */
	bool standstill_seed_after_gap = true;
	/** icp and lines+icp: in a log without odometry (readings that never
	 * moved, counted frozen), ICP is also seeded where the constant
	 * velocity's translation alone carries the robot from the last match,
	 * without its turn: a turn rate measured from the matches over one
	 * interval (a scan per 1-3 s) and carried over the next puts the
	 * prediction tens of degrees off where the robot drove straight on. */
	bool straight_seed_without_odometry = true;
	/** icp and lines+icp with point ICP: an ICP match whose fit ([icp]
	 * seed_fit_sigma_m) is more than this below the fit of the prediction
	 * itself is not used (issue 12: a match that fits worse than the
	 * prediction is never accepted); the line match stands in only if it
	 * does not fit worse than the prediction either. Negative = off. */
	double max_fit_loss_vs_prediction = 0.02;
	/** icp_matcher = mrpt with [icp] engine = cached: an ICP restart's two
	 * seeds (turned by +-k steps) are aligned on two threads at once; same
	 * results, less wall time. */
	bool parallel_restarts = true;
	/** icp and lines+icp: a scan with more points than this is matched with
	 * every k-th of them (ICP, its fit and covariance, the point fallback of
	 * line matching; k = ceil(points / this)); lines are extracted from every
	 * point, keyframes keep their own spacing. 0 = every point. */
	int max_match_points = 0;

	template <class V>
	void visit(V& v)
	{
		v.choice("method", method, {"odometry", "lines", "icp", "lines+icp", "map", "lines+map"});
		v.real("match_every_m", match_every_m, 0.0, 100.0);
		v.degrees("match_every_deg", match_every_rad, 0.0, 360.0);
		v.real("icp_every_m", icp_every_m, 0.0, 100.0);
		v.degrees("icp_every_deg", icp_every_rad, 0.0, 360.0);
		v.flag("icp_always", icp_always);
		v.real("match_every_s", match_every_s, 0.0, 1e6);
		v.real("standstill_max_m", standstill_max_m, 0.0, 100.0);
		v.degrees("standstill_max_deg", standstill_max_rad, 0.0, 360.0);
		v.flag("stalled_point_to_line", stalled_point_to_line);
		v.real("stalled_unconstrained_max_fraction", stalled_unconstrained_max_fraction, 0.0, 0.5);
		v.real("stalled_normal_radius_m", stalled_normal_radius_m, 0.01, 10.0);
		v.flag("unconstrained_axis_without_odometry", unconstrained_axis_without_odometry);
		v.flag("unconstrained_axis_after_gap", unconstrained_axis_after_gap);
		v.flag("unconstrained_axis_after_freeze", unconstrained_axis_after_freeze);
		v.real("stalled_keyframe_every_s", stalled_keyframe_every_s, 0.0, 1000.0);
		v.flag("keyframes_after_icp_only", keyframes_after_icp_only);
		v.real("keyframe_without_icp_spacings", keyframe_without_icp_spacings, 1.0, 1000.0);
		v.choice("icp_matcher", icp_matcher, {"mrpt", "point_to_line", "mrpt+point_to_line"});
		v.flag("seed_refused_matches", seed_refused_matches);
		v.flag("standstill_seed_after_gap", standstill_seed_after_gap);
		v.flag("straight_seed_without_odometry", straight_seed_without_odometry);
		v.real("max_fit_loss_vs_prediction", max_fit_loss_vs_prediction, -1.0, 1.0);
		v.flag("parallel_restarts", parallel_restarts);
		v.integer("max_match_points", max_match_points, 0, 1000000);
	}
};

/** Builds the estimator named by options.method; `cfg` gives it access to
 * its own INI sections; it records its sub-stages in `timer`. */
std::unique_ptr<CPoseEstimator> createPoseEstimator(const TPoseEstimationOptions& options,
													const mrpt::config::CConfigFileBase& cfg,
													common::CStageTimer& timer);

/** Dead reckoning: composes odometry increments from the start pose (0,0,0).
 * Unknown increments leave the pose unchanged (nothing better is known). */
class COdometryPoseEstimator : public CPoseEstimator
{
   public:
	std::string name() const override { return "odometry"; }
	TPoseEstimate update(const TOdometryIncrement& increment, const common::TRangeData& scan,
						 const std::vector<bool>* excludedBeams) override;

   private:
	mrpt::poses::CPose2D m_pose;
};

}  // namespace hslam::slam
