/* hslam: scan-to-local-map front-end (see CLocalMapPoseEstimator.h). */
#include <hslam/common/options_io.h>
#include <hslam/matching/scan_points.h>
#include <hslam/slam/CLocalMapPoseEstimator.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::slam
{
namespace
{
fusion::TPoseVec toVec(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
mrpt::poses::CPose2D toPose(const fusion::TPoseVec& v) { return {v[0], v[1], v[2]}; }
}  // namespace

std::vector<std::string> CLocalMapPoseEstimator::sections()
{
	std::vector<std::string> s{"motion_prior", "keyframes", "map_matching", "recovery", "ukf", "odometry_noise",
							   "line_extraction", "line_matching"};
	for (const auto& m : features::lineExtractorMethods()) s.push_back(features::lineExtractorSection(m));
	return s;
}

CLocalMapPoseEstimator::CLocalMapPoseEstimator(const TPoseEstimationOptions& options,
											   const mrpt::config::CConfigFileBase& cfg, common::CStageTimer& timer)
	: m_options(options),
	  m_ukfOptions(common::loadedOptions<TUkfSectionOptions>(cfg, "ukf")),
	  m_odometryNoise(common::loadedOptions<fusion::TOdometryNoiseOptions>(cfg, "odometry_noise")),
	  m_recovery(common::loadedOptions<TRecoveryOptions>(cfg, "recovery")),
	  m_motion(common::loadedOptions<CMotionPrior::TOptions>(cfg, "motion_prior")),
	  m_keyframes(common::loadedOptions<matching::CKeyframeStore::TOptions>(cfg, "keyframes")),
	  m_matcher(common::loadedOptions<matching::CPointToLineIcp::TOptions>(cfg, "map_matching")),
	  m_ukf(m_ukfOptions.filter),
	  m_noise(m_ukfOptions.adaptation),
	  m_timer(timer),
	  m_extraction(common::loadedOptions<TLineExtractionChoice>(cfg, "line_extraction")),
	  m_lineMatcher(common::loadedOptions<matching::CLineScanMatcher::TOptions>(cfg, "line_matching"))
{
	if (usesLines())
		m_extractor = features::createLineExtractor(m_extraction.method, cfg,
													features::lineExtractorSection(m_extraction.method));
}

void CLocalMapPoseEstimator::saveOptions(mrpt::config::CConfigFileBase& out) const
{
	common::saveOptions(m_motion.options(), out, "motion_prior");
	common::saveOptions(m_keyframes.options(), out, "keyframes");
	common::saveOptions(m_matcher.options(), out, "map_matching");
	common::saveOptions(m_recovery, out, "recovery");
	common::saveOptions(m_ukfOptions, out, "ukf");
	common::saveOptions(m_odometryNoise, out, "odometry_noise");
	if (!usesLines()) return;
	common::saveOptions(m_extraction, out, "line_extraction");
	common::saveOptions(m_lineMatcher.options(), out, "line_matching");
}

mrpt::poses::CPose2D CLocalMapPoseEstimator::currentPose() const { return toPose(m_ukf.pose()); }

void CLocalMapPoseEstimator::predict(const TMotionPrior& prior)
{
	common::CStageTimer::CScope t(m_timer, "ukf");
	const fusion::TPoseVec u = toVec(prior.delta);
	const Eigen::Matrix3d Q = prior.source == TMotionPrior::ESource::odometry
								  ? fusion::odometryIncrementCovariance(m_odometryNoise, u)
								  : prior.covariance;
	m_ukf.predict(u, Q);
	m_sinceMatch = m_sinceMatch + prior.delta;
	if (prior.source != TMotionPrior::ESource::odometry) m_unreliableSinceMatch = true;
}

bool CLocalMapPoseEstimator::dueForMatch(const TMotionPrior& prior) const
{
	return prior.source != TMotionPrior::ESource::odometry || m_unreliableSinceMatch || m_failedMatches > 0 ||
		   m_sinceMatch.norm() >= m_options.match_every_m ||
		   std::abs(m_sinceMatch.phi()) >= m_options.match_every_rad;
}

std::vector<mrpt::poses::CPose2D> CLocalMapPoseEstimator::recoverySeeds(const mrpt::poses::CPose2D& centre) const
{
	std::vector<mrpt::poses::CPose2D> out;
	const int nxy = static_cast<int>(std::floor(m_recovery.window_xy_m / m_recovery.step_xy_m + 1e-9));
	const int nth = static_cast<int>(std::floor(m_recovery.window_theta_rad / m_recovery.step_theta_rad + 1e-9));
	for (int k = -nth; k <= nth; ++k)
		for (int i = -nxy; i <= nxy; ++i)
			for (int j = -nxy; j <= nxy; ++j)
				if (i || j || k)
					out.emplace_back(centre.x() + i * m_recovery.step_xy_m, centre.y() + j * m_recovery.step_xy_m,
									 centre.phi() + k * m_recovery.step_theta_rad);
	return out;
}

std::optional<matching::TMapMatch> CLocalMapPoseEstimator::bestMatch(
	const matching::TOrientedPoints& points, const std::vector<mrpt::poses::CPose2D>& seedPoses) const
{
	std::optional<matching::TMapMatch> best;
	for (const auto& seed : seedPoses)
	{
		matching::TMapMatch m = m_matcher.match(m_localMap, points, seed);
		if (!best || m.cost < best->cost) best = std::move(m);
	}
	return best;
}

std::vector<mrpt::poses::CPose2D> CLocalMapPoseEstimator::seeds(const common::TRangeData& scan, TPoseEstimate& estimate)
{
	const mrpt::poses::CPose2D predicted = currentPose();
	std::vector<mrpt::poses::CPose2D> out{predicted};
	// Heading is what odometry gets most wrong (10-20 deg after sharp turns on
	// real logs) and what narrows ICP's basin most: seeds at +-1 and +-2
	// standard deviations when it is uncertain.
	const double sth = std::sqrt(std::max(0.0, m_ukf.covariance()(2, 2)));
	if (sth > m_recovery.heading_seeds_above_rad)
		for (const double k : {1.0, -1.0, 2.0, -2.0})
			out.push_back(predicted + mrpt::poses::CPose2D(0, 0, k * std::min(sth, m_recovery.window_theta_rad / 2)));
	if (!usesLines()) return out;
	matching::TLineScanFrame frame;
	{
		common::CStageTimer::CScope t(m_timer, "line_extraction");
		frame.lines = m_extractor->extract(scan);
		frame.points = scan.points.xy;
		frame.pointsMap = matching::toPointsMap(frame.points);
	}
	if (m_previousFrame)
	{
		common::CStageTimer::CScope t(m_timer, "line_matching");
		const mrpt::poses::CPose2D odo = predicted - m_previousFramePose;
		const Eigen::Matrix3d odoCov = fusion::odometryIncrementCovariance(m_odometryNoise, toVec(odo));
		const auto m = m_lineMatcher.match(*m_previousFrame, frame, odo, odoCov);
		if (m.quality != matching::EMatchQuality::failed) out.push_back(m_previousFramePose + m.pose);
	}
	estimate.lines = frame.lines;
	m_previousFrame = std::move(frame);
	return out;
}

void CLocalMapPoseEstimator::fuse(const matching::TMapMatch& m, TPoseEstimate& estimate)
{
	common::CStageTimer::CScope t(m_timer, "ukf");
	const bool weak = m.match.quality == matching::EMatchQuality::weak;
	const Eigen::Matrix3d R = m_noise.effectiveCovariance(m.match.covariance, weak);
	auto result = m_ukf.updateAbsolute(toVec(m.match.pose), R, m_ukfOptions.gate_nis);
	if (!weak) m_motion.observeMatch(m.match.pose, m.match.covariance, result.accepted, result.nis, m_matchTime_s);
	const bool slip = !result.accepted && m.inlier_fraction_at_guess < m_recovery.slip_max_guess_inliers &&
					  m.match.score >= m_recovery.slip_min_inliers;
	if (slip)
	{  // the prediction does not fit the map, the match does: re-anchor on the match
		m_ukf.reset(toVec(m.match.pose), R);
		result.accepted = true;
		estimate.match_method = "map:slip";
	}
	else
	{
		if (result.accepted) m_noise.observeNis(result.nis);
		estimate.match_method = m.match.method;
	}
	estimate.match_quality = m.match.quality;
	estimate.match_accepted = result.accepted;
	estimate.match_nis = result.nis;
	m_failedMatches = result.accepted ? 0 : m_failedMatches + 1;
}

void CLocalMapPoseEstimator::matchAndFuse(const common::TRangeData& scan, const std::vector<bool>* excluded,
										  TPoseEstimate& estimate)
{
	std::vector<mrpt::poses::CPose2D> seedPoses = seeds(scan, estimate);
	const matching::TOrientedPoints points = matching::pointsWithNormals(scan.points, m_keyframes.options(), excluded);
	common::CStageTimer::CScope t(m_timer, "map_matching");
	m_localMap.update(m_keyframes, m_keyframes.window(seedPoses.front()));
	std::optional<matching::TMapMatch> m = bestMatch(points, seedPoses);
	const bool recovering = m_unreliableSinceMatch || m_failedMatches >= m_recovery.after_failed_matches;
	const bool poor = !m || m->match.quality != matching::EMatchQuality::good;
	if (recovering && poor)
	{
		common::CStageTimer::CScope r(m_timer, "recovery_search");
		auto wide = bestMatch(points, recoverySeeds(seedPoses.front()));
		if (wide && (!m || wide->cost < m->cost)) m = std::move(wide), estimate.match_method = "map:recovery";
	}
	estimate.matched = true;
	if (!m || m->match.quality == matching::EMatchQuality::failed || !m->better_than_guess)
	{
		estimate.match_method = "map", estimate.match_quality = matching::EMatchQuality::failed;
		++m_failedMatches;
		return;
	}
	fuse(*m, estimate);
	if (estimate.match_accepted) m_unreliableSinceMatch = false;
}

TPoseEstimate CLocalMapPoseEstimator::update(const TOdometryIncrement& increment, const common::TRangeData& scan,
											 const std::vector<bool>* excludedBeams)
{
	TPoseEstimate estimate;
	const TMotionPrior prior = m_motion.prior(increment, scan.t_s);
	estimate.motion_prior = prior.reason;
	m_matchTime_s = scan.t_s;
	if (m_started) predict(prior);
	if (!m_started || dueForMatch(prior))
	{
		if (m_started && !m_keyframes.empty()) matchAndFuse(scan, excludedBeams, estimate);
		else if (usesLines()) seeds(scan, estimate);  // keeps the first frame for the line matcher
		m_started = true;
		m_sinceMatch = mrpt::poses::CPose2D();
		m_previousFramePose = currentPose();
	}
	const mrpt::poses::CPose2D pose = currentPose();
	const bool trusted = m_keyframes.empty() || estimate.match_accepted ||
						 (!m_unreliableSinceMatch && m_failedMatches == 0) ||
						 m_failedMatches >= m_recovery.reseed_after_failed_matches;
	if (trusted && m_keyframes.wantsKeyframe(pose))
		estimate.keyframe_id = static_cast<long>(m_keyframes.add(scan.points, pose, m_ukf.covariance(), scan.t_s));
	m_motion.observePose(pose, scan.t_s);
	estimate.pose = pose;
	estimate.covariance = m_ukf.covariance();
	return estimate;
}

}  // namespace hslam::slam
