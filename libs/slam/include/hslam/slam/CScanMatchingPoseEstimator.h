/* hslam: the hybrid pose estimator of thesis 4.4-4.5 (figure 114): odometry
 * predicts the pose in a UKF; every match_every_m of travel or
 * match_every_deg of rotation (thesis: 0.1 m / 5 deg) a scan matcher
 * measures it and the UKF fuses the measurement.
 *
 *   lines      line features of this scan vs the previous matched scan
 *              (CLineScanMatcher), a relative measurement fused against the
 *              UKF's clone of the previous pose.
 *   icp        MRPT ICP of this scan against the recent keyframes
 *              (CKeyframePointMap), seeded by the UKF prediction; an absolute
 *              measurement in the map frame.
 *   lines+icp  lines first; when the line match is weak or failed (corridors,
 *              clutter: thesis 4.4.6, 4.5.5) or if icp_always, ICP refines it,
 *              seeded by the line result (thesis future work 5.2).
 *
 * Robustness: every measurement is gated by its normalised innovation
 * (a wrong match is rejected, the UKF keeps predicting from odometry), weak
 * matches get an inflated covariance, and each matcher's covariance scale is
 * adapted online from its innovations (fusion::CAdaptiveMeasurementNoise).
 * Odometry is trusted only while it behaves like odometry (CMotionPrior,
 * [motion_prior]): a gap, frozen or stalled wheel readings, or a jump make the
 * prediction the constant velocity of the last estimates, and the scan is
 * then matched at every scan (ICP included) until odometry is trusted again,
 * so a log without usable odometry is tracked by matching alone. A gap marker
 * (no odometry at all) keeps the large covariance of [ukf]
 * unknown_motion_*_std, so the next match is free to correct it. A match also
 * runs every match_every_s of time while odometry reports no travel, so
 * odometry that stopped or creeps is noticed; one after odometry reported no
 * travel at all (standstill_max_m / _deg) is refined point-to-line and judged
 * by the point-to-segment fit ([icp] standstill_*): point-to-point measures
 * favour zero motion against a reference scan taken from the claimed pose.
 * While odometry counts as stalled (readings that creep), every ICP match is
 * checked that way (stalled_point_to_line) and keyframes also come on time
 * (stalled_keyframe_every_s), since estimated travel may not come.
 * The ICP reference holds only scans that ICP placed (keyframes_after_icp_only:
 * a keyframe due runs ICP; one carried by odometry and line matches would
 * bring their drift into the map), unless none was for
 * keyframe_without_icp_spacings keyframe spacings.
 *
 * INI sections: [pose_estimation], [line_extraction], [line_extraction_<method>], [line_matching],
 * [icp], [icp_map], [ukf], [odometry_noise], [motion_prior]. */
#pragma once

#include <hslam/features/CLineExtractor.h>
#include <hslam/fusion/CAdaptiveMeasurementNoise.h>
#include <hslam/fusion/CPoseUKF.h>
#include <hslam/fusion/odometry_noise.h>
#include <hslam/matching/CIcpMatcher.h>
#include <hslam/matching/CKeyframePointMap.h>
#include <hslam/matching/CKeyframeStore.h>
#include <hslam/matching/CLocalPointMap.h>
#include <hslam/matching/CPointToLineIcp.h>
#include <hslam/matching/CLineScanMatcher.h>
#include <hslam/slam/CGapSearch.h>
#include <hslam/slam/CMotionPrior.h>
#include <hslam/slam/CPoseEstimator.h>

#include <functional>
#include <memory>
#include <optional>

namespace hslam::slam
{
/** [line_extraction] section: which extractor; its own keys are in
 * [line_extraction_<method>]. */
struct TLineExtractionChoice
{
	std::string method = "derivative";  //!< "derivative" (thesis 4.4.2), "iep" or "ransac"

	template <class V>
	void visit(V& v)
	{
		v.choice("method", method, {"derivative", "iep", "ransac"});
	}
};

/** [ukf] section: filter parameters, gating and measurement-noise adaptation. */
struct TUkfSectionOptions
{
	fusion::CPoseUKF::TOptions filter;
	fusion::CAdaptiveMeasurementNoise::TOptions adaptation;
	/** Reject a match whose NIS exceeds this. 50 (chi-square 3 dof tail ~1e-10)
	 * rejects only gross mismatches: the textbook 16.3 (99.9 %) also rejected
	 * correct ICP corrections after the 10-20 deg odometry heading errors of
	 * real logs and let the estimate drift (measured: csail ATE 3.8 m vs 0.96 m). */
	double gate_nis = 50.0;
	/** The gate of weak scan-to-map (ICP) matches, e.g. ICP pairing few
	 * points: the heavy tails gate_nis allows for are odometry's, and a weak
	 * match that contradicts the prediction is more likely wrong than right
	 * (sim-open-hall.ini with a 5.6 m scanner: 17 paired points, NIS 21.8,
	 * 0.75 m and 8.6 deg off). Frame-to-frame line matches keep gate_nis:
	 * most of the thesis matcher's are weak (aces, method lines: ATE 3.4 m,
	 * 6.0 m with this gate). 16.27 = chi-square 3 dof, 99.9 %. */
	double weak_gate_nis = 16.27;
	double unknown_motion_xy_std_m = 1.0;  //!< odometry gap: std of the unknown translation
	double unknown_motion_theta_std_rad = 30.0 * M_PI / 180.0;  //!< odometry gap: std of the unknown rotation
	/** A well-constrained ICP match beyond the gate is taken, with the
	 * prediction's covariance widened until it passes, when the scan refutes
	 * the prediction: the match fits the keyframes at least
	 * refuted_prediction_min_fit ([icp] seed_fit_sigma_m likelihood) and by
	 * refuted_prediction_min_fit_gain more than the scan at the predicted
	 * pose does. Odometry's heading errors at real logs' fast turns are
	 * heavy-tailed, not Gaussian. 0 = never (the gate alone). */
	double refuted_prediction_min_fit = 0.6;
	double refuted_prediction_min_fit_gain = 0.3;

	template <class V>
	void visit(V& v)
	{
		filter.visit(v);
		adaptation.visit(v);
		v.real("gate_nis", gate_nis, 0.1, 1e9);
		v.real("weak_gate_nis", weak_gate_nis, 0.1, 1e9);
		v.real("unknown_motion_xy_std_m", unknown_motion_xy_std_m, 0.01, 100.0);
		v.degrees("unknown_motion_theta_std_deg", unknown_motion_theta_std_rad, 0.1, 180.0);
		v.real("refuted_prediction_min_fit", refuted_prediction_min_fit, 0.0, 1.0);
		v.real("refuted_prediction_min_fit_gain", refuted_prediction_min_fit_gain, 0.0, 1.0);
	}
};

class CScanMatchingPoseEstimator : public CPoseEstimator
{
   public:
	CScanMatchingPoseEstimator(const TPoseEstimationOptions& options, const mrpt::config::CConfigFileBase& cfg,
							   common::CStageTimer& timer);

	std::string name() const override { return m_options.method; }
	TPoseEstimate update(const TOdometryIncrement& increment, const common::TRangeData& scan,
						 const std::vector<bool>* excludedBeams) override;

	/** Sections read, with their effective values (for config_used.ini). */
	void saveOptions(mrpt::config::CConfigFileBase& out) const override;
	static std::vector<std::string> sections();

   private:
	bool usesLines() const { return m_options.method != "icp"; }
	bool usesIcp() const { return m_options.method != "lines"; }
	bool usesPointToLine() const { return m_options.icp_matcher != "mrpt"; }
	/** ICP matches against the points of the recent keyframes (CKeyframePointMap), not the store's local map. */
	bool matchesKeyframePoints() const { return m_options.icp_matcher != "point_to_line"; }

	bool dueByTime(double t_s) const;
	bool dueForMatch(double t_s) const;
	bool dueForIcp() const;
	/** The ICP matcher for the match now due: without the degeneracy cap after a
	 * gap or for a timed match, the standstill check for a timed match after no
	 * travel at all (standstill_max_*), m_icp otherwise. */
	const matching::CIcpMatcher& icpForThisMatch() const;
	matching::TLineScanFrame makeFrame(const common::TRangeData& scan);
	void predict(const TOdometryIncrement& increment, const TMotionPrior& prior);
	/** Whether this scan is matched by ICP: when due (or its line match
	 * failed) and the method asks for ICP beside a usable line match. */
	bool wantsIcp(const std::optional<matching::TPoseMatch>& lineMatch) const;
	void matchAndFuse(matching::TLineScanFrame& frame, const common::TRangeData& scan, TPoseEstimate& estimate);
	/** Fuses the ICP match, else the line match, unless the prediction fits
	 * the keyframes better (max_fit_loss_vs_prediction). */
	void fuseChosenMatch(const matching::TLineScanFrame& frame, const std::optional<matching::TPoseMatch>& lineMatch,
						 std::optional<matching::TPoseMatch>& icpMatch, const matching::TPoseMatch* refusedTrack,
						 TPoseEstimate& estimate);
	/** Whether a match fitting the keyframes with `fit` ([icp]
	 * seed_fit_sigma_m; 0 = not computed) fits worse than the prediction,
	 * by more than max_fit_loss_vs_prediction (`predictionFit` gives the
	 * prediction's fit). */
	bool fitsWorseThanPrediction(double fit, const std::function<double()>& predictionFit) const;
	/** The same for a line match (a pose relative to the cloned pose), its fit computed here. */
	bool lineFitsWorseThanPrediction(const matching::TPoseMatch& lineMatch, const matching::TLineScanFrame& frame,
									 const std::function<double()>& predictionFit);
	/** Restarts the filter where the refused matches put the robot when
	 * they made the motion prior declare a stall (seed_refused_matches). */
	void restartAtRefusedMatches(const TMotionPrior& prior, double t_s);
	/** Appends `seed` unless one within 0.05 m / 1 deg is already there;
	 * returns whether it was appended. */
	static bool addSeedIfNew(std::vector<mrpt::poses::CPose2D>& seeds, const mrpt::poses::CPose2D& seed);
	/** Whether the ICP result of a later seed replaces an earlier one. */
	bool betterSeedResult(const matching::TPoseMatch& later, const matching::TPoseMatch& earlier) const;
	/** ICP from each seed (world frame, preferred first); the best result,
	 * its covariance widened over competing basins when `predictionTrusted`
	 * (competing_basins.h). `results` receives each seed's result, in seed
	 * order (fewer when the loop stopped early). */
	std::optional<matching::TPoseMatch> runIcp(const matching::TLineScanFrame& frame, const common::TRangeData& scan,
												const std::vector<mrpt::poses::CPose2D>& seedsWorld,
												bool predictionTrusted, std::vector<matching::TPoseMatch>& results);
	std::optional<matching::TPoseMatch> runPointToLineIcp(const common::TRangeData& scan,
														   const std::vector<mrpt::poses::CPose2D>& seedsWorld);
	void addKeyframeIfDue(const common::TRangeData& scan, const TPoseEstimate& estimate);
	/** A match that is not good or fits poorly, after a gap of unknown
	 * motion or (after_poor_match) with odometry, is retried from the wide
	 * search's pose; the clearly better fit is kept. */
	void searchWiderIfPoor(const matching::TLineScanFrame& frame, const common::TRangeData& scan,
						   std::optional<matching::TPoseMatch>& icpMatch);
	/** The wide search's pose of `frame` (world), if any (CGapSearch). */
	std::optional<mrpt::poses::CPose2D> wideSearchSeed(const matching::TLineScanFrame& frame);
	/** Whether a direction the scan leaves loose is left to the
	 * constant-velocity prior now: while stalled, in a log without
	 * odometry, after lost readings once a velocity is known. */
	bool priorHoldsLooseAxes() const;
	/** Then a direction the scan's surfaces leave unconstrained gets a huge
	 * variance in `match` ([pose_estimation]
	 * stalled_unconstrained_max_fraction). */
	void leaveUnconstrainedAxisToPrior(matching::TPoseMatch& match, const matching::TLineScanFrame& frame);
	/** The points (robot frame) with a reference point within maxDistance_m
	 * when the robot stands at `pose` (world). */
	std::vector<mrpt::math::TPoint2D> pointsTheReferenceHolds(const std::vector<mrpt::math::TPoint2D>& points,
															  const mrpt::poses::CPose2D& pose, double maxDistance_m);
	/** Updates the filter with `match`; `refusedTrack`, when set, is the
	 * refused-match seed's result competing with it, which the motion prior
	 * then counts as another refusal instead of the match's confirmation. */
	void fuse(const matching::TPoseMatch& match, bool relative, fusion::CAdaptiveMeasurementNoise& noise,
			  TPoseEstimate& estimate, const matching::TPoseMatch* refusedTrack = nullptr,
			  const std::function<double()>& predictionFit = {});
	/** Widens the prediction when an absolute match beyond the gate fits the
	 * keyframes well and the scan at the predicted pose does not ([ukf]
	 * refuted_prediction_min_fit...); true if it did. */
	bool widenRefutedPrediction(const matching::TPoseMatch& match, const Eigen::Matrix3d& R,
								const std::function<double()>& predictionFit);
	mrpt::poses::CPose2D currentPose() const;

	TPoseEstimationOptions m_options;
	TUkfSectionOptions m_ukfOptions;
	fusion::TOdometryNoiseOptions m_odometryNoise;
	TLineExtractionChoice m_extraction;
	std::unique_ptr<features::CLineExtractor> m_extractor;
	matching::CLineScanMatcher m_lineMatcher;
	matching::CIcpMatcher m_icp;
	matching::CIcpMatcher m_icpWithoutPrior;  //!< m_icp without the degeneracy cap (prior not odometry)
	matching::CIcpMatcher m_icpStandstill;  //!< m_icpWithoutPrior checking a claimed standstill (icpForThisMatch)
	matching::CKeyframePointMap m_keyframes;  //!< icp_matcher = mrpt
	matching::CKeyframeStore m_store;  //!< icp_matcher = point_to_line: keyframes with normals...
	matching::CLocalPointMap m_localMap;  //!< ...the local map of the window around the robot...
	matching::CPointToLineIcp m_pointToLine;  //!< ...and the matcher
	CMotionPrior m_motion;
	CGapSearch m_gapSearch;  //!< wide search for the first match after a gap ([gap_search])
	fusion::CPoseUKF m_ukf;
	fusion::CAdaptiveMeasurementNoise m_lineNoise, m_icpNoise;
	common::CStageTimer& m_timer;

	bool m_started = false;
	std::optional<matching::TLineScanFrame> m_previousFrame;  //!< last matched scan
	mrpt::poses::CPose2D m_sinceMatch;  //!< odometry since the last matched scan (its robot frame)
	mrpt::poses::CPose2D m_sinceIcp;  //!< odometry since the last ICP match
	Eigen::Matrix3d m_sinceMatchCov = Eigen::Matrix3d::Zero();
	/** Sum of the non-odometry priors' covariances since the last match (the gap search's window). */
	Eigen::Matrix3d m_priorCovSinceMatch = Eigen::Matrix3d::Zero();
	bool m_gapVelocityMeasured = false;  //!< every such prior since the last match was velocity_measured
	double m_lastKeyframe_s = -1e300;  //!< scan time of the last ICP keyframe
	bool m_stalledSinceMatch = false;  //!< the prior was a stall's constant velocity since the last match
	/** the prior was a constant velocity standing in for readings that came
	 * (frozen, jumping, stalled) since the last match, not for lost ones */
	bool m_readingsOverruledSinceMatch = false;
	bool m_lostReadingsSinceMatch = false;  //!< a prior since the last match stood for lost readings
	bool m_frozenReadingsSinceMatch = false;  //!< ...for readings that froze after motion (TMotionPrior::froze_after_motion)
	bool m_gapSinceMatch = false;  //!< the prior was not odometry since the last match: match (and ICP) now
	bool m_odometryHasMoved = false;  //!< some odometry increment so far was not zero
	double m_lastIcp_s = 0;  //!< time of the last ICP match
	double m_matchTime_s = 0;  //!< time of the scan being matched
	bool m_timedMatch = false;  //!< this match is due by time only (match_every_s)
};

}  // namespace hslam::slam
