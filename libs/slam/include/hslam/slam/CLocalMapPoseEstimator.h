/* hslam: the front-end that "never loses the robot" (issue 12): scan-to-
 * local-map matching fused with a motion prior in the UKF of thesis 4.5.
 *
 * Per scan:
 *   motion prior (CMotionPrior: odometry, or constant velocity when odometry
 *   is missing, frozen, stalled or jumps) -> UKF prediction
 *   -> when due (match_every_m / match_every_deg of predicted travel, or at
 *      every scan while the prior is not odometry): the scan's returns up to
 *      [keyframes] max_range_m, minus the beams the dynamic filter predicts
 *      on people, decimated, are matched against the local map of keyframes
 *      (CPointToLineIcp, degeneracy-aware) from the prediction and, with
 *      method lines+map, the thesis' line-matcher result (4.4.2 iii) as a
 *      second seed;
 *   -> recovery (after a gap, an unreliable prior, a failed or rejected
 *      match): a wider search over a window of seeds before accepting;
 *   -> acceptance: a match is fused only if it fits better than the
 *      prediction (TMapMatch::better_than_guess) and is not failed; the UKF
 *      gate (NIS) rejects it unless the prediction itself clearly does not
 *      fit the map (inliers at the guess below slip_max_guess_inliers while
 *      the match has at least slip_min_inliers): then odometry slipped and
 *      the filter is re-anchored on the match ("odometry_slip");
 *   -> keyframe store (CKeyframeStore): the scan becomes a keyframe every
 *      insertion_distance_m / insertion_angle_deg; the loop-closure back-end
 *      reads the same store.
 *
 * INI sections: [pose_estimation], [motion_prior], [keyframes],
 * [map_matching], [recovery], [ukf], [odometry_noise], and with lines+map
 * [line_extraction], [line_extraction_<method>], [line_matching]. */
#pragma once

#include <hslam/features/CLineExtractor.h>
#include <hslam/fusion/CAdaptiveMeasurementNoise.h>
#include <hslam/fusion/CPoseUKF.h>
#include <hslam/fusion/odometry_noise.h>
#include <hslam/matching/CKeyframeStore.h>
#include <hslam/matching/CLineScanMatcher.h>
#include <hslam/matching/CLocalPointMap.h>
#include <hslam/matching/CPointToLineIcp.h>
#include <hslam/slam/CMotionPrior.h>
#include <hslam/slam/CPoseEstimator.h>
#include <hslam/slam/CScanMatchingPoseEstimator.h>

#include <memory>
#include <optional>

namespace hslam::slam
{
/** [recovery]: the wider search after a gap or a failed match. */
struct TRecoveryOptions
{
	double window_xy_m = 1.0;  //!< seeds on a grid of +- this (m)...
	double step_xy_m = 0.5;  //!< ...with this spacing
	double window_theta_rad = 30.0 * M_PI / 180.0;  //!< and +- this rotation...
	double step_theta_rad = 10.0 * M_PI / 180.0;  //!< ...with this spacing
	int after_failed_matches = 2;  //!< also search after this many failed/rejected matches in a row
	double heading_seeds_above_rad = 2.0 * M_PI / 180.0;  //!< extra seeds at +-1, +-2 heading stds above this std
	/** Keyframes are added only at matched (or odometry-trusted) poses; after
	 * this many failed matches in a row the map is re-seeded anyway (the robot
	 * left the mapped area: keep the drift rather than stop mapping). */
	int reseed_after_failed_matches = 10;
	double slip_max_guess_inliers = 0.3;  //!< prediction fits worse than this...
	double slip_min_inliers = 0.6;  //!< ...and the match at least this: odometry slipped

	template <class V>
	void visit(V& v)
	{
		v.real("window_xy_m", window_xy_m, 0.0, 20.0);
		v.real("step_xy_m", step_xy_m, 0.01, 20.0);
		v.degrees("window_theta_deg", window_theta_rad, 0.0, 180.0);
		v.degrees("step_theta_deg", step_theta_rad, 0.1, 180.0);
		v.integer("after_failed_matches", after_failed_matches, 1, 1000);
		v.degrees("heading_seeds_above_deg", heading_seeds_above_rad, 0.0, 180.0);
		v.integer("reseed_after_failed_matches", reseed_after_failed_matches, 1, 100000);
		v.real("slip_max_guess_inliers", slip_max_guess_inliers, 0.0, 1.0);
		v.real("slip_min_inliers", slip_min_inliers, 0.0, 1.0);
	}
};

class CLocalMapPoseEstimator : public CPoseEstimator
{
   public:
	CLocalMapPoseEstimator(const TPoseEstimationOptions& options, const mrpt::config::CConfigFileBase& cfg,
						   common::CStageTimer& timer);

	std::string name() const override { return m_options.method; }
	TPoseEstimate update(const TOdometryIncrement& increment, const common::TRangeData& scan,
						 const std::vector<bool>* excludedBeams) override;
	void saveOptions(mrpt::config::CConfigFileBase& out) const override;
	static std::vector<std::string> sections();

	const matching::CKeyframeStore& keyframes() const { return m_keyframes; }

   private:
	bool usesLines() const { return m_options.method == "lines+map"; }
	void predict(const TMotionPrior& prior);
	bool dueForMatch(const TMotionPrior& prior) const;
	std::vector<mrpt::poses::CPose2D> seeds(const common::TRangeData& scan, TPoseEstimate& estimate);
	std::optional<matching::TMapMatch> bestMatch(const matching::TOrientedPoints& points,
												 const std::vector<mrpt::poses::CPose2D>& seeds) const;
	std::vector<mrpt::poses::CPose2D> recoverySeeds(const mrpt::poses::CPose2D& centre) const;
	void fuse(const matching::TMapMatch& match, TPoseEstimate& estimate);
	void matchAndFuse(const common::TRangeData& scan, const std::vector<bool>* excluded, TPoseEstimate& estimate);
	mrpt::poses::CPose2D currentPose() const;

	TPoseEstimationOptions m_options;
	TUkfSectionOptions m_ukfOptions;
	fusion::TOdometryNoiseOptions m_odometryNoise;
	TRecoveryOptions m_recovery;
	CMotionPrior m_motion;
	matching::CKeyframeStore m_keyframes;
	matching::CLocalPointMap m_localMap;
	matching::CPointToLineIcp m_matcher;
	fusion::CPoseUKF m_ukf;
	fusion::CAdaptiveMeasurementNoise m_noise;
	common::CStageTimer& m_timer;
	// lines+map only: the thesis' line matcher as a seed
	TLineExtractionChoice m_extraction;
	std::unique_ptr<features::CLineExtractor> m_extractor;
	matching::CLineScanMatcher m_lineMatcher;
	std::optional<matching::TLineScanFrame> m_previousFrame;
	mrpt::poses::CPose2D m_previousFramePose;

	bool m_started = false;
	mrpt::poses::CPose2D m_sinceMatch;  //!< predicted motion since the last match
	bool m_unreliableSinceMatch = false;  //!< a non-odometry prior since the last accepted match
	int m_failedMatches = 0;  //!< failed or rejected matches in a row
	double m_matchTime_s = 0;  //!< time of the scan being processed
};

}  // namespace hslam::slam
