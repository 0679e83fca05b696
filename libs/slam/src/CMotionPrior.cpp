/* hslam: the motion prior of the front-end (see CMotionPrior.h). */
#include <hslam/slam/CMotionPrior.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace hslam::slam
{
TMotionPrior CMotionPrior::constantVelocity(double dt_s, const std::string& reason) const
{
	TMotionPrior p;
	p.source = TMotionPrior::ESource::constant_velocity;
	p.reason = reason;
	p.delta = mrpt::poses::CPose2D(m_velocity.x() * dt_s, m_velocity.y() * dt_s, m_velocity.z() * dt_s);
	const double sxy = m_options.cv_xy_std_m + m_options.cv_xy_std_mps * dt_s;
	const double sth = m_options.cv_theta_std_rad + m_options.cv_theta_std_rad_s * dt_s;
	p.covariance = Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal();
	return p;
}

bool CMotionPrior::isJump(const mrpt::poses::CPose2D& delta, double dt_s) const
{
	const double dt = std::max(dt_s, m_options.min_interval_s);
	if (dt <= 0) return false;  // no usable interval: nothing to compare with
	return delta.norm() > m_options.max_speed_mps * dt || std::abs(delta.phi()) > m_options.max_turn_rate_rad_s * dt;
}

Eigen::Vector3d CMotionPrior::possibleVelocity(const mrpt::poses::CPose2D& d, double dt_s) const
{
	Eigen::Vector3d v(d.x() / dt_s, d.y() / dt_s, mrpt::math::wrapToPi(d.phi()) / dt_s);
	const double speed = v.head<2>().norm();
	if (speed > m_options.max_speed_mps) v.head<2>() *= m_options.max_speed_mps / speed;
	v.z() = std::clamp(v.z(), -m_options.max_turn_rate_rad_s, m_options.max_turn_rate_rad_s);
	return v;
}

bool CMotionPrior::movingTooFastToStop(double dt_s) const
{
	return m_options.max_decel_mps2 > 0 && m_lastOdometrySpeed_mps > m_options.max_decel_mps2 * dt_s;
}

bool CMotionPrior::zerosFollowMotion() const
{
	// the readings' own speed before them: zeros between the steps of
	// readings that creep (1 mm in ARCOS units now and then) are no motion
	return m_zeroIncrements > 0 && m_lastOdometrySpeed_mps * m_zeroRun_s >= m_options.creep_min_motion_m;
}

void CMotionPrior::noteZeroRun(const TOdometryIncrement& increment, double dt_s)
{
	if (m_zeroIncrements == 0)
	{
		m_velocityBeforeZeros.reset();
		m_lastOdometrySpeed_mps = increment.delta.norm() / std::max(dt_s, m_options.min_interval_s);
		return;
	}
	m_zeroRun_s = m_zeroIncrements == 1 ? dt_s : m_zeroRun_s + dt_s;  // a gap may have cut the run
	if (m_zeroIncrements != 1 || !movingTooFastToStop(dt_s)) return;
	m_velocityBeforeZeros = m_velocity;  // of the estimates up to the scan before the first zero
	m_poseBeforeZeros = m_lastPose;
	m_poseBeforeZeros_s = m_lastPose_s;
}

TMotionPrior CMotionPrior::prior(const TOdometryIncrement& increment, double t_s)
{
	const double dt = m_haveScan ? std::clamp(t_s - m_lastScan_s, 0.0, 10.0) : 0.0;
	m_lastScan_s = t_s, m_haveScan = true;
	m_lastOdometry = increment.known ? increment.delta : mrpt::poses::CPose2D();
	m_odometrySinceMatch = m_odometrySinceMatch + m_lastOdometry;
	m_lastOdometryKnown = increment.known;
	TMotionPrior p = choose(increment, dt, t_s);
	if (p.source == TMotionPrior::ESource::odometry) m_faultAtSpeed = false;
	p.velocity_measured = p.source != TMotionPrior::ESource::odometry && m_faultAtSpeed;
	return p;
}

TMotionPrior CMotionPrior::choose(const TOdometryIncrement& increment, double dt, double t_s)
{
	if (!increment.known)
	{
		// odometry lost while the last reading moved faster than any stop explains
		if (m_zeroIncrements == 0 && !m_inGap && movingTooFastToStop(dt))
			m_faultAtSpeed = true;
		m_inGap = true;
		m_zeroIncrements = 0;
		return constantVelocity(dt, "gap");
	}
	m_inGap = false;
	const bool zero = increment.delta.norm() == 0 && increment.delta.phi() == 0;
	m_zeroIncrements = zero ? m_zeroIncrements + 1 : 0;
	noteZeroRun(increment, dt);
	if (m_zeroIncrements > 0)
		if (const auto p = zerosPrior(dt, t_s)) return *p;
	m_faultAtSpeed = false;  // a jump or a stall: what the velocity says is in doubt
	if (isJump(increment.delta, dt)) return constantVelocity(dt, "jump");
	m_stalled = odometryStalled(t_s);
	if (m_stalled) return constantVelocity(dt, TMotionPrior::kStalled);
	TMotionPrior p;
	p.delta = increment.delta;
	return p;
}

std::optional<TMotionPrior> CMotionPrior::zerosPrior(double dt_s, double t_s)
{
	const bool frozen = m_zeroIncrements >= m_options.frozen_min_scans, afterMotion = zerosFollowMotion();
	if (!frozen && !(afterMotion && m_velocityKnown && m_options.zeros_after_motion_unknown)) return std::nullopt;
	TMotionPrior p = !frozen				 ? constantVelocity(dt_s, "zeros")
					 : m_velocityBeforeZeros ? frozenAtSpeed(dt_s, t_s)
											 : constantVelocity(dt_s, "frozen");
	p.froze_after_motion = afterMotion;
	return p;
}

TMotionPrior CMotionPrior::frozenAtSpeed(double dt_s, double t_s)
{
	m_velocity = *m_velocityBeforeZeros, m_velocityBeforeZeros.reset(), m_faultAtSpeed = true;
	if (!m_havePose || t_s <= m_poseBeforeZeros_s) return constantVelocity(dt_s, "frozen");
	// The estimates of the zeros' first scans followed the zeros (they are
	// only declared a fault at frozen_min_scans): the prior catches up, to
	// where the held velocity carries the last estimate before them. A
	// corridor's axis would keep that lag to the end (simulated floor,
	// readings frozen 10 s at 0.8 m/s: 0.33 m).
	TMotionPrior p = constantVelocity(t_s - m_poseBeforeZeros_s, "frozen");
	p.delta = (m_poseBeforeZeros + p.delta) - m_lastPose;
	return p;
}

bool CMotionPrior::odometryStalled(double t_s) const
{
	double odo_m = 0, odo_rad = 0, est_m = 0, est_rad = 0;
	size_t intervals = 0;
	for (const auto& i : m_recent)
		if (i.t_s >= t_s - m_options.disagreement_window_s)  // the list is pruned only when the next pose comes
			odo_m += i.odometry_m, odo_rad += i.odometry_rad, est_m += i.estimate_m, est_rad += i.estimate_rad,
				++intervals;
	const double k = m_options.disagreement_ratio;
	const bool moved = est_m >= m_options.disagreement_min_motion_m,
			   turned = est_rad >= m_options.disagreement_min_rotation_rad;
	const bool distanceAgrees = moved && odo_m >= k * est_m;
	const double turnRatio = distanceAgrees ? std::min(k, m_options.turn_only_disagreement_ratio) : k;
	if ((moved && odo_m < k * est_m) || (turned && odo_rad < turnRatio * est_rad) ||
		(m_options.stall_needs_creeping ? m_rejectedCreepingInARow : m_rejectedInARow) >=
			m_options.rejected_matches_for_stall)
		return true;
	// stalled: stays so until the motion within the window shows odometry
	// agrees again (a window without any interval holds no evidence either way)
	return m_stalled && m_options.stall_ends_on_agreement && intervals > 0 && !moved && !turned;
}

void CMotionPrior::observeMatch(const mrpt::poses::CPose2D& measured, const Eigen::Matrix3d& covariance,
								bool accepted, double nis, double t_s)
{
	if (!constrainsTranslation(covariance)) return;
	const bool contradicted = !accepted || (m_options.contradicting_nis > 0 && nis > m_options.contradicting_nis);
	m_rejectedInARow = contradicted ? m_rejectedInARow + 1 : 0;
	m_rejectedCreepingInARow = contradicted && odometryCreptSince(measured) ? m_rejectedCreepingInARow + 1 : 0;
	m_odometrySinceMatch = mrpt::poses::CPose2D();
	if (stalledBaseline())
		measureStalledVelocity(measured, t_s);
	else if (m_havePreviousMatch && t_s - m_previousMatch_s >= m_options.min_interval_s &&
			 t_s > m_previousMatch_s && (m_stalled || m_rejectedInARow > 1 || m_faultAtSpeed))
	{  // the estimate follows odometry (or a held velocity) until the filter lets go: take the measured velocity
		m_velocity = possibleVelocity(measured - m_previousMatch, t_s - m_previousMatch_s);
		m_measuredVelocity_s = t_s;
	}
	m_previousMatch = measured, m_previousMatch_s = t_s, m_havePreviousMatch = true;
}

void CMotionPrior::measureStalledVelocity(const mrpt::poses::CPose2D& measured, double t_s)
{
	// Simulated floor laps, readings creeping: a match 0.39 m ahead of the
	// lagging estimate after a bare stretch, measured against the match
	// 0.2 s before, set 2.7 m/s (truth 0.8); the prior then ran 20 m ahead.
	// Matches are kept over the stall window, or twice the baseline if longer.
	const double keep_s = std::max(m_options.disagreement_window_s, 2.0 * m_options.stalled_velocity_baseline_s);
	while (!m_stalledMatches.empty() && m_stalledMatches.front().first < t_s - keep_s) m_stalledMatches.pop_front();
	const std::pair<double, mrpt::poses::CPose2D>* base = nullptr;
	for (const auto& m : m_stalledMatches)
		if (m.first <= t_s - m_options.stalled_velocity_baseline_s) base = &m;
	if (base)
	{
		const Eigen::Vector3d v = possibleVelocity(measured - base->second, t_s - base->first);
		m_velocity.head<2>() = v.head<2>();
		m_measuredVelocity_s = t_s;
	}
	m_stalledMatches.emplace_back(t_s, measured);
}

bool CMotionPrior::odometryCreptSince(const mrpt::poses::CPose2D& measured) const
{
	if (!m_havePreviousMatch) return true;
	const mrpt::poses::CPose2D matched = measured - m_previousMatch;
	const double k = m_options.disagreement_ratio;
	const double matched_rad = std::abs(mrpt::math::wrapToPi(matched.phi()));
	const bool showedTranslation = m_odometrySinceMatch.norm() >= std::max(m_options.creep_min_motion_m, k * matched.norm());
	const bool showedRotation =
		std::abs(m_odometrySinceMatch.phi()) >= std::max(m_options.creep_min_rotation_rad, k * matched_rad);
	return !showedTranslation && !showedRotation;
}

bool CMotionPrior::constrainsTranslation(const Eigen::Matrix3d& covariance) const
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(covariance.topLeftCorner<2, 2>());
	return eig.eigenvalues().maxCoeff() <= m_options.measured_max_std_m * m_options.measured_max_std_m;
}

std::optional<mrpt::poses::CPose2D> CMotionPrior::contradictedMatchSeed(double t_s) const
{
	if (m_rejectedInARow == 0 || !m_havePreviousMatch) return std::nullopt;
	const double dt = t_s - m_previousMatch_s;
	if (dt < 0 || dt > m_options.disagreement_window_s) return std::nullopt;
	return m_previousMatch + mrpt::poses::CPose2D(m_velocity.x() * dt, m_velocity.y() * dt, m_velocity.z() * dt);
}

void CMotionPrior::restarted()
{
	// Laser-only building, 8 m scanner: the restart 1.1 m ahead, measured
	// over 0.4 s as motion, set 2.9 m/s, and where the next matches left the
	// corridor's axis to the prior the estimate ran 4.8 m ahead in a second.
	m_poseHistory.clear();
	m_havePose = false, m_velocityKnown = false;
}

void CMotionPrior::observePose(const mrpt::poses::CPose2D& pose, double t_s)
{
	if (m_havePose && t_s > m_lastPose_s)
	{
		const mrpt::poses::CPose2D d = pose - m_lastPose;  // in the previous robot frame
		// The velocity over min_interval_s at least: from the newest estimate that old.
		while (m_poseHistory.size() > 1 && m_poseHistory[1].first <= t_s - m_options.min_interval_s)
			m_poseHistory.pop_front();
		const auto& [base_s, basePose] = m_poseHistory.front();
		// Through a fault at speed the velocity measured before it is held:
		// the estimates then are its own extrapolations (and the zeros' first
		// scans stood still), so re-measuring it from them made it decay
		// (simulated floor, readings frozen at 0.8 m/s: 0.52 m/s within a
		// second, ATE 1.30 m; held, 0.24 m). Only well-constrained matches
		// re-measure it then (observeMatch): a stop is seen where walls are.
		if (t_s > base_s && !m_faultAtSpeed)
		{
			const Eigen::Vector3d v = possibleVelocity(pose - basePose, t_s - base_s);
			if (stalledBaseline())
				m_velocity.z() = v.z();  // the translation comes from matches (measureStalledVelocity)
			else if (m_measuredVelocity_s != t_s)
				m_velocity = v;
			m_velocityKnown = true;
		}
		if (m_lastOdometryKnown)
			m_recent.push_back({t_s, m_lastOdometry.norm(), std::abs(m_lastOdometry.phi()), d.norm(),
								std::abs(mrpt::math::wrapToPi(d.phi()))});
		while (!m_recent.empty() && m_recent.front().t_s < t_s - m_options.disagreement_window_s) m_recent.pop_front();
	}
	m_lastPose = pose, m_lastPose_s = t_s, m_havePose = true;
	m_poseHistory.emplace_back(t_s, pose);
}

}  // namespace hslam::slam
