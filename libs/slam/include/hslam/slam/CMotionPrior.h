/* hslam: what the front-end believes about the motion between two scans
 * before matching (issue 12, "laser only" and "odometry gap" classes).
 *
 * Odometry is trusted only while it behaves like odometry:
 *  - unknown  (a gap marker, no odometry at all): constant-velocity prior;
 *  - zeros    (exact zeros after readings that moved, before they count
 *             as frozen: zeros_after_motion_unknown): the same prior, the
 *             scans deciding between a stop and a fault;
 *  - frozen   (frozen_min_scans consecutive increments of exactly zero,
 *             i.e. wheel readings that stopped changing: a stalled driver or
 *             a log without odometry but with constant readings): the robot
 *             may be moving, so the same constant-velocity prior is used; a
 *             robot that really stands still is then found still by matching;
 *  - stalled  (over the last disagreement_window_s the estimate moved at
 *             least disagreement_min_motion_m but odometry less than
 *             disagreement_ratio of that, or the same in rotation:
 *             "wheel readings nearly constant" without being exactly so; or
 *             the filter rejected rejected_matches_for_stall well-constrained
 *             matches in a row while the readings did not show the matched
 *             motion (stall_needs_creeping: noisy readings that move are no
 *             stall): a filter that trusts creeping odometry
 *             rejects the matches that contradict it, so the estimate alone
 *             would never move; a match it accepted with a normalised
 *             innovation above contradicting_nis counts as rejected too:
 *             against a prediction a few millimetres wide a 0.12 m match
 *             passes the gate and moves the estimate by 2 mm). A stall ends
 *             only once the estimate moved enough within the window to judge
 *             odometry and odometry agreed (stall_ends_on_agreement), not
 *             merely because the estimate stopped moving;
 *  - jump     (an increment faster than max_speed_mps / max_turn_rate_rad_s
 *             over the scan interval: readings resuming after a stall with
 *             the motion of the whole stall, a wrap, a reset): unknown too.
 * Speeds are judged over min_interval_s at least: logged scan and odometry
 * stamps are not synchronised better than that. Real logs hold scans 20 ms
 * apart (intel: 8 of 910); over 20 ms an ordinary increment looked like a
 * jump, and a matched 33 deg turn became a velocity of 29 rad/s that the
 * constant-velocity prior extrapolated over the next seconds, losing the
 * robot (issue 12, "one slip splits a building").
 * The constant-velocity prior uses the velocity of the estimated poses over
 * the last min_interval_s at least (velocity()), or of the last two measured
 * poses when the filter rejected them, never faster than max_speed_mps /
 * max_turn_rate_rad_s, with a standard deviation growing with the interval,
 * so matching against the map carries the robot alone (laser-only logs).
 * After any unreliable stretch the next match is a recovery (wider search). */
#pragma once

#include <hslam/slam/COdometryTracker.h>

#include <Eigen/Core>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <optional>
#include <string>

namespace hslam::slam
{
struct TMotionPrior
{
	mrpt::poses::CPose2D delta;  //!< predicted motion since the previous scan (its robot frame)
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  //!< only for non-odometry sources
	enum class ESource
	{
		odometry,
		constant_velocity
	} source = ESource::odometry;
	std::string reason;  //!< "", "gap", "frozen", "zeros", kStalled, "jump"
	static constexpr const char* kStalled = "stalled";
	/** Odometry was judged stalled (readings that creep): a constant-velocity prior. */
	bool stalled() const { return reason == kStalled; }
	/** A constant-velocity prior whose velocity was measured on trusted
	 * odometry: the readings froze or stopped coming while the robot moved
	 * faster than any stop explains ([motion_prior] max_decel_mps2), so the
	 * robot still moves at that velocity; matching need not measure a
	 * direction the scan leaves loose. */
	bool velocity_measured = false;
	/** A "zeros" or "frozen" prior for readings that stopped changing after
	 * they moved (not a log's first readings at rest, not the steps of
	 * readings that creep): see CMotionPrior::zerosFollowMotion(). */
	bool froze_after_motion = false;
};

class CMotionPrior
{
   public:
	struct TOptions
	{
		int frozen_min_scans = 3;  //!< zero increments in a row before odometry counts as frozen
		double max_speed_mps = 3.0;  //!< faster increments are jumps (P3-DX: 1.2 m/s)
		double max_turn_rate_rad_s = 300.0 * M_PI / 180.0;  //!< faster turns are jumps
		double cv_xy_std_m = 0.1;  //!< constant-velocity prior: std floor (m)...
		double cv_xy_std_mps = 0.5;  //!< ...plus this per second of interval (acceleration)
		double cv_theta_std_rad = 5.0 * M_PI / 180.0;  //!< std floor (rad)...
		double cv_theta_std_rad_s = 30.0 * M_PI / 180.0;  //!< ...plus this per second
		double disagreement_window_s = 3.0;  //!< see file comment ("stalled")
		double disagreement_min_motion_m = 0.3;
		double disagreement_min_rotation_rad = 20.0 * M_PI / 180.0;
		double disagreement_ratio = 0.25;
		/** A stall ends only once the estimate moved enough over the window
		 * to judge odometry (disagreement_min_motion_m or
		 * disagreement_min_rotation_deg) and odometry did not disagree with
		 * it. Without this, a stall ends as soon as the estimate stops moving
		 * (a corridor where matching no longer sees the motion) and hands the
		 * estimate back to readings that creep. */
		bool stall_ends_on_agreement = true;
		/** Where the distance agrees (the estimate moved
		 * disagreement_min_motion_m within the window and the readings at
		 * least disagreement_ratio of it), a stall judged by rotation alone
		 * needs the readings' turn below this fraction of the estimate's:
		 * the readings are alive, and a turn that lags or is noisy (a
		 * fifth of the scans' at csail's fast turns) is matching's to
		 * correct, while a heading that stopped changing reports next to
		 * nothing. At disagreement_ratio (the old rule), csail's scans
		 * 25-27 (readings turned 13 deg where the scans turned 73, over
		 * the same 2.1 m) declared a stall whose recovery search put scan
		 * 28 3.2 m and 118 deg off. */
		double turn_only_disagreement_ratio = 0.1;
		double measured_max_std_m = 0.1;  //!< see observeMatch()
		int rejected_matches_for_stall = 3;  //!< see file comment ("stalled")
		/** Rejected matches count towards a stall only where odometry did
		 * not show the matched motion: neither creep_min_motion_m and
		 * disagreement_ratio of the matched translation, nor
		 * creep_min_rotation_deg and that ratio of the matched rotation.
		 * Readings that creep show neither; noisy readings that move do. */
		bool stall_needs_creeping = true;
		double creep_min_motion_m = 0.02;
		double creep_min_rotation_rad = 2.0 * M_PI / 180.0;
		double contradicting_nis = 16.27;  //!< an accepted match above this NIS counts as rejected (0 = off)
		double min_interval_s = 0.25;  //!< speeds are judged over at least this interval (see file comment)
		/** Odometry that drops to exact zeros from a speed no robot could
		 * shed in one scan interval at this deceleration froze while moving:
		 * the constant velocity is the one from before the zeros (the
		 * estimates of the zeros' first scans followed them), held through
		 * the fault unless well-constrained matches re-measure it, and the
		 * first frozen prior catches up on those scans. Readings that stop
		 * coming at such a speed keep the velocity the same way. 0 = off. */
		double max_decel_mps2 = 2.0;
		/** Exact zeros that follow motion are unknown motion until they
		 * count as frozen (frozen_min_scans): a constant-velocity prior as
		 * for lost readings, so the scans decide between moving on and a
		 * stop (the standstill seed after a gap, [pose_estimation]
		 * standstill_seed_after_gap). They follow motion when the last
		 * moving reading's speed would have carried the robot
		 * creep_min_motion_m over the zeros so far (the readings' speed,
		 * not the estimates': zeros between the steps of readings that
		 * creep are no motion). Zeros faster than any stop explains
		 * (max_decel_mps2) are such zeros too, and are declared frozen at
		 * speed at frozen_min_scans as before. false: followed as a stop
		 * until then; at a scan a second a robot at 0.8 m/s may stop within
		 * one interval, and three scans stood still before the readings
		 * counted as frozen (stress matrix slowscan+freeze: floor 2.75 m). */
		bool zeros_after_motion_unknown = true;
		/** While stalled, the translation velocity is measured only between
		 * well-constrained matches at least this far apart (s); the
		 * estimates between them follow the prior wherever the scan leaves
		 * a direction loose, and one correction measured over 0.2-0.4 s as
		 * motion became a speed the prior then carried down the next bare
		 * corridor. The turn rate still comes from the estimates (heading
		 * is measured). 0 = from the estimates as otherwise. */
		double stalled_velocity_baseline_s = 1.0;

		template <class V>
		void visit(V& v)
		{
			v.integer("frozen_min_scans", frozen_min_scans, 1, 1000);
			v.real("max_speed_mps", max_speed_mps, 0.1, 100.0);
			v.degrees("max_turn_rate_deg_s", max_turn_rate_rad_s, 1.0, 10000.0);
			v.real("cv_xy_std_m", cv_xy_std_m, 0.0, 10.0);
			v.real("cv_xy_std_mps", cv_xy_std_mps, 0.0, 10.0);
			v.degrees("cv_theta_std_deg", cv_theta_std_rad, 0.0, 180.0);
			v.degrees("cv_theta_std_deg_s", cv_theta_std_rad_s, 0.0, 1000.0);
			v.real("disagreement_window_s", disagreement_window_s, 0.1, 1000.0);
			v.real("disagreement_min_motion_m", disagreement_min_motion_m, 0.01, 100.0);
			v.degrees("disagreement_min_rotation_deg", disagreement_min_rotation_rad, 1.0, 3600.0);
			v.real("disagreement_ratio", disagreement_ratio, 0.0, 1.0);
			v.flag("stall_ends_on_agreement", stall_ends_on_agreement);
			v.real("turn_only_disagreement_ratio", turn_only_disagreement_ratio, 0.0, 1.0);
			v.real("measured_max_std_m", measured_max_std_m, 0.001, 100.0);
			v.integer("rejected_matches_for_stall", rejected_matches_for_stall, 1, 1000);
			v.flag("stall_needs_creeping", stall_needs_creeping);
			v.real("creep_min_motion_m", creep_min_motion_m, 0.0, 10.0);
			v.degrees("creep_min_rotation_deg", creep_min_rotation_rad, 0.0, 180.0);
			v.real("contradicting_nis", contradicting_nis, 0.0, 1e6);
			v.real("min_interval_s", min_interval_s, 0.0, 10.0);
			v.real("max_decel_mps2", max_decel_mps2, 0.0, 100.0);
			v.flag("zeros_after_motion_unknown", zeros_after_motion_unknown);
			v.real("stalled_velocity_baseline_s", stalled_velocity_baseline_s, 0.0, 100.0);
		}
	};

	CMotionPrior() : CMotionPrior(TOptions()) {}
	explicit CMotionPrior(const TOptions& options) : m_options(options) {}
	const TOptions& options() const { return m_options; }

	/** The prior for the interval ending at a scan at `t_s`. */
	TMotionPrior prior(const TOdometryIncrement& increment, double t_s);
	/** The estimated pose at the scan at `t_s` (feeds the velocity). */
	void observePose(const mrpt::poses::CPose2D& pose, double t_s);
	/** The filter was restarted elsewhere (contradictedMatchSeed): the jump
	 * is no motion, so neither the velocity nor the stall window measures
	 * across it; the velocity stays the refused matches' own. */
	void restarted();
	/** A pose the scan matcher measured at the scan at `t_s` (world frame),
	 * whether the filter `accepted` it and its normalised innovation squared;
	 * used only if its translation is constrained in every direction (std <=
	 * measured_max_std_m: a corridor match says nothing about motion along
	 * the axis). */
	void observeMatch(const mrpt::poses::CPose2D& measured, const Eigen::Matrix3d& covariance, bool accepted,
					  double nis, double t_s);
	/** Whether a match of this covariance (x m, y m, theta rad) constrains
	 * the translation in every direction (std <= measured_max_std_m). */
	bool constrainsTranslation(const Eigen::Matrix3d& covariance) const;
	/** Odometry since the last well-constrained match did not show the motion to `measured` (stall_needs_creeping). */
	bool odometryCreptSince(const mrpt::poses::CPose2D& measured) const;
	/** While the filter contradicts the well-constrained matches (the last
	 * one rejected, or accepted above contradicting_nis): where the last of
	 * them puts the robot at `t_s`, moved on at velocity(); a seed for the
	 * next match, since the estimate the filter keeps may be left behind
	 * further than ICP reaches (laser-only sample started mid-run: 9 m lost
	 * while three matches 0.1-0.8 m ahead were refused). nullopt otherwise or
	 * after disagreement_window_s. */
	std::optional<mrpt::poses::CPose2D> contradictedMatchSeed(double t_s) const;
	/** Whether the filter has refused rejected_matches_for_stall
	 * well-constrained matches in a row (one of the ways to "stalled"). */
	bool refusingMatches() const { return m_rejectedInARow >= m_options.rejected_matches_for_stall; }
	/** Robot-frame velocity (m/s, m/s, rad/s) of the recent estimates. */
	Eigen::Vector3d velocity() const { return m_velocity; }
	/** Whether velocity() was measured from estimates since the start or the last restart. */
	bool velocityKnown() const { return m_velocityKnown; }

   private:
	TMotionPrior constantVelocity(double dt_s, const std::string& reason) const;
	/** Bookkeeping of a run of zero increments (max_decel_mps2). */
	void noteZeroRun(const TOdometryIncrement& increment, double dt_s);
	/** prior() without the bookkeeping of velocity_measured. */
	TMotionPrior choose(const TOdometryIncrement& increment, double dt_s, double t_s);
	/** The prior for exact zeros: "frozen" from frozen_min_scans, "zeros"
	 * before that if they follow motion (zeros_after_motion_unknown), else
	 * nullopt (followed as a stop). */
	std::optional<TMotionPrior> zerosPrior(double dt_s, double t_s);
	/** The prior once zeros that began at speed are declared frozen (max_decel_mps2). */
	TMotionPrior frozenAtSpeed(double dt_s, double t_s);
	bool isJump(const mrpt::poses::CPose2D& delta, double dt_s) const;
	/** Whether the last moving reading was at a speed no stop within dt_s
	 * explains (max_decel_mps2). */
	bool movingTooFastToStop(double dt_s) const;
	/** Whether the current zeros follow motion: the last moving reading's
	 * speed would have carried the robot creep_min_motion_m over them. */
	bool zerosFollowMotion() const;
	/** Whether the intervals within disagreement_window_s before t_s say
	 * that odometry is stalled (file comment). */
	bool odometryStalled(double t_s) const;
	/** Velocity of motion `d` over dt_s, limited to what the robot can do. */
	Eigen::Vector3d possibleVelocity(const mrpt::poses::CPose2D& d, double dt_s) const;

	struct TIntervalMotion
	{
		double t_s, odometry_m, odometry_rad, estimate_m, estimate_rad;
	};
	/** Intervals with known odometry within disagreement_window_s. One
	 * without odometry (a gap, the unknown motion before the first reading)
	 * is no evidence that the wheels stalled and is not kept: taken as zero
	 * odometry, the turn the scans saw before a log's first odometry reading
	 * made the next 3 s "stalled", and a constant-velocity prior then carried
	 * the robot 6 m through a 10 s pause in which it moved 0.9 m (aces cut at
	 * entry 6: ATE 1.17 m with the front-end alone). */
	std::deque<TIntervalMotion> m_recent;
	bool m_stalled = false;  //!< the last prior was "stalled"
	int m_rejectedInARow = 0;  //!< well-constrained matches the filter rejected in a row
	/** ...while the readings did not show the matched motion (odometryCreptSince) */
	int m_rejectedCreepingInARow = 0;
	mrpt::poses::CPose2D m_odometrySinceMatch;  //!< odometry since the last well-constrained match
	mrpt::poses::CPose2D m_previousMatch;  //!< the last well-constrained measured pose...
	double m_previousMatch_s = 0;  //!< ...its time
	bool m_havePreviousMatch = false;
	double m_measuredVelocity_s = -1;  //!< time of the scan whose velocity came from the matches
	mrpt::poses::CPose2D m_lastOdometry;  //!< odometry of the latest interval (zero if unknown)
	bool m_lastOdometryKnown = false;  //!< the latest interval had odometry

	TOptions m_options;
	int m_zeroIncrements = 0;
	/** The velocity when the current run of zero increments began, kept when
	 * the run began at a speed no stop explains (max_decel_mps2). */
	std::optional<Eigen::Vector3d> m_velocityBeforeZeros;
	mrpt::poses::CPose2D m_poseBeforeZeros;  //!< the estimate at the scan before those zeros...
	double m_poseBeforeZeros_s = 0;  //!< ...and its time
	double m_lastOdometrySpeed_mps = 0;  //!< of the latest non-zero increment
	double m_zeroRun_s = 0;  //!< time since the latest non-zero increment, while its zeros last
	bool m_velocityKnown = false;  //!< m_velocity was measured from estimates (velocityKnown())
	bool m_faultAtSpeed = false;  //!< the current fault began at speed (velocity_measured; the velocity is held)
	bool m_inGap = false;  //!< the latest increment was unknown
	double m_lastScan_s = 0, m_lastPose_s = 0;
	bool m_haveScan = false, m_havePose = false;
	mrpt::poses::CPose2D m_lastPose;
	std::deque<std::pair<double, mrpt::poses::CPose2D>> m_poseHistory;  //!< estimates of the last min_interval_s
	Eigen::Vector3d m_velocity = Eigen::Vector3d::Zero();
	/** Well-constrained matches while stalled, of the last
	 * disagreement_window_s or twice stalled_velocity_baseline_s. */
	std::deque<std::pair<double, mrpt::poses::CPose2D>> m_stalledMatches;
	/** While stalled: the translation velocity between the newest match
	 * and one at least stalled_velocity_baseline_s older, if any. */
	void measureStalledVelocity(const mrpt::poses::CPose2D& measured, double t_s);
	bool stalledBaseline() const { return m_stalled && m_options.stalled_velocity_baseline_s > 0; }
};

}  // namespace hslam::slam
