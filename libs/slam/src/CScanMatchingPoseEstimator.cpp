#include <hslam/common/options_io.h>
#include <hslam/matching/alignment_fit.h>
#include <hslam/matching/competing_basins.h>
#include <hslam/matching/scan_constraint.h>
#include <hslam/matching/scan_points.h>
#include <hslam/slam/CScanMatchingPoseEstimator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>
#include <mrpt/math/wrap2pi.h>

namespace hslam::slam
{
namespace
{
fusion::TPoseVec toVec(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
mrpt::poses::CPose2D toPose(const fusion::TPoseVec& v) { return {v[0], v[1], v[2]}; }
/** The ICP used without an informative prediction (gap, frozen or stalled
 * odometry, a timed match). */
matching::CIcpMatcher::TOptions withoutPrior(matching::CIcpMatcher::TOptions o)
{
	o.geometric.degenerate_min_fraction = 0;
	// Restarts keep the result nearest the prediction among those pairing as
	// many points; for a badly fitting first result that is only a choice
	// when the prediction means something (simulated lab with its odometry
	// removed, lines+icp: ATE 0.537 m with these restarts, below 0.1 without).
	o.restart_below_fit = 0;
	o.restart_below_good_points = false;  // the same choice by prior distance
	return o;
}

/** A timed match after odometry reported no travel at all ([pose_estimation]
 * standstill_max_*) checks its claim that the robot stood still. If the
 * claim is true the reference scan was taken from the same pose, and both
 * scans sample every wall at the same bearings: point-to-point ICP and its
 * nearest-point fit then favour zero motion however far the robot went
 * along a corridor (laser-only sample started mid-corridor at entries 110
 * and 2200: the estimate stayed put for 12-15 m, ATE 3.9 / 3.0 m). The check
 * is refined point-to-line and judged by the point-to-segment fit
 * ([icp] standstill_*), which have no such pull. */
matching::CIcpMatcher::TOptions standstillCheck(matching::CIcpMatcher::TOptions o)
{
	o = withoutPrior(o);
	o.point_to_line_steps = o.standstill_point_to_line_steps;
	o.seed_fit_max_segment_m = o.standstill_fit_max_segment_m;
	return o;
}
}  // namespace

std::vector<std::string> CScanMatchingPoseEstimator::sections()
{
	std::vector<std::string> s{"line_extraction", "line_matching",	"icp",		  "icp_map",
							   "keyframes",		  "map_matching",	"ukf",		  "odometry_noise",
							   "motion_prior",	  "gap_search"};
	for (const auto& m : features::lineExtractorMethods()) s.push_back(features::lineExtractorSection(m));
	return s;
}

CScanMatchingPoseEstimator::CScanMatchingPoseEstimator(const TPoseEstimationOptions& options,
													   const mrpt::config::CConfigFileBase& cfg,
													   common::CStageTimer& timer)
	: m_options(options),
	  m_ukfOptions(common::loadedOptions<TUkfSectionOptions>(cfg, "ukf")),
	  m_odometryNoise(common::loadedOptions<fusion::TOdometryNoiseOptions>(cfg, "odometry_noise")),
	  m_extraction(common::loadedOptions<TLineExtractionChoice>(cfg, "line_extraction")),
	  m_extractor(features::createLineExtractor(m_extraction.method, cfg,
												features::lineExtractorSection(m_extraction.method))),
	  m_lineMatcher(common::loadedOptions<matching::CLineScanMatcher::TOptions>(cfg, "line_matching")),
	  m_icp(common::loadedOptions<matching::CIcpMatcher::TOptions>(cfg, "icp")),
	  m_icpWithoutPrior(withoutPrior(m_icp.options())),
	  m_icpStandstill(standstillCheck(m_icp.options())),
	  m_keyframes(common::loadedOptions<matching::CKeyframePointMap::TOptions>(cfg, "icp_map")),
	  m_store(common::loadedOptions<matching::CKeyframeStore::TOptions>(cfg, "keyframes")),
	  m_pointToLine(common::loadedOptions<matching::CPointToLineIcp::TOptions>(cfg, "map_matching")),
	  m_motion(common::loadedOptions<CMotionPrior::TOptions>(cfg, "motion_prior")),
	  m_gapSearch(common::loadedOptions<TGapSearchOptions>(cfg, "gap_search")),
	  m_ukf(m_ukfOptions.filter),
	  m_lineNoise(m_ukfOptions.adaptation),
	  m_icpNoise(m_ukfOptions.adaptation),
	  m_timer(timer)
{
	if (!options.parallel_restarts || std::thread::hardware_concurrency() < 2) return;
	const auto pool = std::make_shared<common::CTaskPool>(2);  // restarts come in pairs
	for (auto* icp : {&m_icp, &m_icpWithoutPrior, &m_icpStandstill}) icp->setRestartPool(pool);
}

void CScanMatchingPoseEstimator::saveOptions(mrpt::config::CConfigFileBase& out) const
{
	common::saveOptions(m_ukfOptions, out, "ukf");
	common::saveOptions(m_odometryNoise, out, "odometry_noise");
	common::saveOptions(m_lineMatcher.options(), out, "line_matching");
	common::saveOptions(m_icp.options(), out, "icp");
	common::saveOptions(m_keyframes.options(), out, "icp_map");
	common::saveOptions(m_store.options(), out, "keyframes");
	common::saveOptions(m_pointToLine.options(), out, "map_matching");
	common::saveOptions(m_motion.options(), out, "motion_prior");
	common::saveOptions(m_gapSearch.options(), out, "gap_search");
	common::saveOptions(m_extraction, out, "line_extraction");
	m_extractor->saveOptions(out, features::lineExtractorSection(m_extraction.method));
}

mrpt::poses::CPose2D CScanMatchingPoseEstimator::currentPose() const { return toPose(m_ukf.pose()); }

bool CScanMatchingPoseEstimator::dueByTime(double t_s) const
{
	// Only while odometry claims (almost) no travel since the last ICP match:
	// when it reports motion, the distance rules decide (matching a moving
	// robot more often than icp_every_m accumulates bias: aces ATE 0.55 m ->
	// 1.46 m with an ICP at every scan).
	const bool odometryStill =
		m_sinceIcp.norm() < m_options.match_every_m && std::abs(m_sinceIcp.phi()) < m_options.match_every_rad;
	return m_options.match_every_s > 0 && odometryStill && t_s - m_lastIcp_s >= m_options.match_every_s;
}

bool CScanMatchingPoseEstimator::dueForMatch(double t_s) const
{
	return m_gapSinceMatch || dueByTime(t_s) || m_sinceMatch.norm() >= m_options.match_every_m ||
		   std::abs(m_sinceMatch.phi()) >= m_options.match_every_rad;
}

const matching::CIcpMatcher& CScanMatchingPoseEstimator::icpForThisMatch() const
{
	// Without an informative prediction (an odometry gap), or to check
	// odometry's report of little or no travel (a timed match), a weakly
	// constrained direction is better measured than not. A report of no
	// travel at all (a standstill) is checked without the point-to-point
	// pull towards zero motion (standstillCheck); slow turns in place are
	// not (simulated floor, four such matches: median ATE over ten starts
	// 0.071 -> 0.078 m when they were).
	// A velocity measured on trusted odometry before the readings froze or
	// stopped at speed is a prediction: a direction the scan leaves loose
	// (a corridor's axis) keeps it. Point ICP there is pulled back to the
	// last keyframe, and without the prediction the estimate stood still
	// through the fault (simulated floor, readings frozen 10 s at 0.8 m/s:
	// ATE 2.75 m; odometry 3.00).
	// Readings that creep (a stall): the constant velocity is no measurement
	// either, and point ICP pins the estimate on the last keyframe's wall
	// samples down a corridor (laser-only building, 8 m scanner: ATE 5.42 ->
	// 3.69 m, docs/pose-estimation.md).
	if (m_stalledSinceMatch && m_options.stalled_point_to_line) return m_icpStandstill;
	if (m_gapSinceMatch) return m_gapVelocityMeasured ? m_icp : m_icpWithoutPrior;
	if (!m_timedMatch) return m_icp;
	const bool claimsStandstill =
		m_sinceIcp.norm() < m_options.standstill_max_m && std::abs(m_sinceIcp.phi()) < m_options.standstill_max_rad;
	return claimsStandstill ? m_icpStandstill : m_icpWithoutPrior;
}

bool CScanMatchingPoseEstimator::dueForIcp() const
{
	return m_gapSinceMatch || m_timedMatch || m_sinceIcp.norm() >= m_options.icp_every_m ||
		   std::abs(m_sinceIcp.phi()) >= m_options.icp_every_rad;
}

matching::TLineScanFrame CScanMatchingPoseEstimator::makeFrame(const common::TRangeData& scan)
{
	matching::TLineScanFrame frame;
	// the scan's points at grazing incidence are not aligned; the keyframes
	// keep them as reference (addKeyframeIfDue), where another view's dense
	// points of the same wall may be their partners
	frame.points = matching::everyKthPoint(
		matching::pointsOffGrazingIncidence(scan.points, m_icp.options().max_incidence_rad),
		static_cast<size_t>(m_options.max_match_points));
	frame.pointsMap = matching::toPointsMap(frame.points);
	if (usesLines())
	{
		common::CStageTimer::CScope t(m_timer, "line_extraction");
		frame.lines = m_extractor->extract(scan);
	}
	return frame;
}

void CScanMatchingPoseEstimator::predict(const TOdometryIncrement& increment, const TMotionPrior& prior)
{
	common::CStageTimer::CScope t(m_timer, "ukf");
	const double sxy = m_ukfOptions.unknown_motion_xy_std_m, sth = m_ukfOptions.unknown_motion_theta_std_rad;
	const Eigen::Matrix3d unknownCov = Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal();
	const fusion::TPoseVec u = toVec(prior.delta);
	if (prior.source == TMotionPrior::ESource::odometry)
		m_ukf.predict(u, fusion::odometryIncrementCovariance(m_odometryNoise, u));
	else  // a gap keeps the wide covariance of [ukf]; frozen/stalled/jump the prior's
		m_ukf.predict(u, increment.known ? prior.covariance : Eigen::Matrix3d(prior.covariance.cwiseMax(unknownCov)));
	m_sinceMatch = m_sinceMatch + prior.delta;
	if (prior.source == TMotionPrior::ESource::odometry && (prior.delta.norm() > 0 || prior.delta.phi() != 0))
		m_odometryHasMoved = true;
	m_sinceIcp = m_sinceIcp + prior.delta;
	if (prior.source != TMotionPrior::ESource::odometry)
	{
		m_priorCovSinceMatch += prior.covariance;
		m_gapVelocityMeasured = (!m_gapSinceMatch || m_gapVelocityMeasured) && prior.velocity_measured;
		m_gapSinceMatch = true;
		m_stalledSinceMatch = m_stalledSinceMatch || prior.stalled();
		m_readingsOverruledSinceMatch = m_readingsOverruledSinceMatch || increment.known;
		m_lostReadingsSinceMatch = m_lostReadingsSinceMatch || !increment.known;
		m_frozenReadingsSinceMatch = m_frozenReadingsSinceMatch || (increment.known && prior.froze_after_motion);
	}
	m_sinceMatchCov = fusion::odometryIncrementCovariance(m_odometryNoise, toVec(m_sinceMatch));
	if (m_gapSinceMatch) m_sinceMatchCov += unknownCov;
}

void CScanMatchingPoseEstimator::restartAtRefusedMatches(const TMotionPrior& prior, double t_s)
{
	// The filter refused rejected_matches_for_stall well-constrained matches
	// in a row: its state, not the matches, is what is wrong. Laser-only
	// sample from entry 150: three refused matches 0.48, 0.84 and 1.17 m
	// ahead (truth 0.48, 0.84, 1.20), and at the next scan ICP from where
	// they put the robot was right, but from the stuck state, next to the
	// only keyframe, a wrong result fitted better (alignment_fit.h).
	if (!m_options.seed_refused_matches || !prior.stalled() || !m_motion.refusingMatches()) return;
	if (const auto refused = m_motion.contradictedMatchSeed(t_s))
		m_ukf.reset(toVec(*refused), prior.covariance), m_motion.restarted();
}

bool CScanMatchingPoseEstimator::addSeedIfNew(std::vector<mrpt::poses::CPose2D>& seeds, const mrpt::poses::CPose2D& seed)
{
	for (const auto& s : seeds)
		if (s.distanceTo(seed) <= 0.05 && std::abs(mrpt::math::wrapToPi(s.phi() - seed.phi())) <= 1.0 * M_PI / 180)
			return false;
	seeds.push_back(seed);
	return true;
}

bool CScanMatchingPoseEstimator::betterSeedResult(const matching::TPoseMatch& later,
												  const matching::TPoseMatch& earlier) const
{
	// By fit when it is computed: goodness cannot tell two basins apart that
	// both pair most points (alignment_fit.h). Five start offsets of aces,
	// csail and intel, front-end alone: heading errors above 1 deg per step
	// summed 180 -> 119, 1162 -> 956, 1175 -> 1088 deg (docs/pose-estimation.md).
	if (m_icp.options().seed_fit_sigma_m > 0) return later.fit > earlier.fit;
	return later.score > earlier.score + m_icp.options().restart_goodness_tolerance;
}

std::optional<matching::TPoseMatch> CScanMatchingPoseEstimator::runIcp(
	const matching::TLineScanFrame& frame, const common::TRangeData& scan, const std::vector<mrpt::poses::CPose2D>& seedsWorld,
	bool predictionTrusted, std::vector<matching::TPoseMatch>& results)
{
	if (seedsWorld.empty()) return std::nullopt;
	common::CStageTimer::CScope t(m_timer, "icp");
	if (!matchesKeyframePoints()) return runPointToLineIcp(scan, seedsWorld);
	if (m_keyframes.empty()) return std::nullopt;
	const mrpt::poses::CPose2D& around = seedsWorld.front();
	const auto matchAt = [&](const matching::CIcpMatcher& icp, const mrpt::poses::CPose2D& seed)
	{
		if (icp.options().engine == "cached")
			return icp.match(m_keyframes.referenceIndex(around), frame.pointsMap, seed, m_ukf.covariance());
		return icp.match(m_keyframes.reference(around), frame.pointsMap, seed, m_ukf.covariance());
	};
	std::optional<matching::TPoseMatch> best;
	results.clear();
	for (const auto& seed : seedsWorld)
	{
		// A later seed must pair clearly more points to replace an earlier
		// one: once that is impossible, it is not run.
		if (best && best->score + m_icp.options().restart_goodness_tolerance >= 1.0) break;
		results.push_back(matchAt(icpForThisMatch(), seed));
		if (!best || betterSeedResult(results.back(), *best)) best = results.back();
	}
	// Seeds that end in different basins fitting about as well: the scan
	// does not decide between them, the prediction should (competing_basins.h).
	// Not while the prediction itself is in doubt: refused matches are then
	// followed and counted (CMotionPrior), and a widened match would count
	// neither way (laser-only sample from entries 6 / 14 / 24: 0.08-0.24 m
	// without widening there, 1.7-3.3 m with it).
	if (best && predictionTrusted) matching::widenForCompetingBasins(*best, results, m_icp.options().competing);
	if (usesPointToLine() && best && best->quality != matching::EMatchQuality::failed)
	{  // refine: point-to-line has no pull towards the seed along walls
		const auto refined = runPointToLineIcp(scan, {best->pose});
		if (refined && refined->quality != matching::EMatchQuality::failed) return refined;
	}
	return best;
}

std::optional<matching::TPoseMatch> CScanMatchingPoseEstimator::runPointToLineIcp(
	const common::TRangeData& scan, const std::vector<mrpt::poses::CPose2D>& seedsWorld)
{
	if (m_store.empty()) return std::nullopt;
	const matching::TOrientedPoints points =
		matching::pointsWithNormals(scan.points, m_store.options());
	m_localMap.update(m_store, m_store.window(seedsWorld.front()));
	std::optional<matching::TMapMatch> best;
	for (const auto& seed : seedsWorld)
	{
		matching::TMapMatch m = m_pointToLine.match(m_localMap, points, seed);
		if (!best || m.cost < best->cost) best = std::move(m);
	}
	// A match that fits the map worse than its own seed is never accepted.
	if (!best->better_than_guess) best->match.quality = matching::EMatchQuality::failed;
	best->match.method = "icp:p2l";
	return best->match;
}

void CScanMatchingPoseEstimator::addKeyframeIfDue(const common::TRangeData& scan, const TPoseEstimate& estimate)
{
	const mrpt::poses::CPose2D pose = currentPose();
	if (!usesIcp()) return;
	const bool icpFused = estimate.match_accepted && estimate.match_method.rfind("icp", 0) == 0;
	if (usesPointToLine() && m_store.wantsKeyframe(pose))
		m_store.add(scan.points, pose, m_ukf.covariance(), scan.t_s);
	// While stalled, keyframes come on time too: by estimated travel alone
	// none came where matching held the estimate back, and the scan was
	// matched against an ever older one (laser-only building, 8 m scanner).
	const bool onTime = m_stalledSinceMatch && m_options.stalled_keyframe_every_s > 0 &&
						scan.t_s - m_lastKeyframe_s >= m_options.stalled_keyframe_every_s;
	// Only where ICP just placed the scan against the map (a keyframe due
	// runs ICP, wantsIcp), unless asked otherwise: a pose that odometry and
	// frame-to-frame line matches carried brings their drift into the map
	// (long corridor at 1.2 m/s with ten times the samples' odometry noise:
	// the heading followed odometry's by 10 deg, ATE 1.08 m against
	// odometry's 2.80; 0.37 m with the rule; docs/pose-estimation.md).
	const bool placedByMap = icpFused || m_keyframes.empty() || !m_options.keyframes_after_icp_only;
	// ...unless no ICP placed one for a long way: a scan that ICP could use
	// as reference is then added as it is (the reference must not stop at
	// the first keyframe); one with fewer than min_good_points is not (a
	// 5.6 m scanner in an open hall, ten to twenty points per scan: ICP then
	// fused few-point matches on such keyframes, RPE 5 m 0.19-0.23 m over
	// four seeds against 0.074 without, odometry 0.078).
	const bool overdue = m_keyframes.wantsKeyframe(pose, m_options.keyframe_without_icp_spacings) &&
						 scan.points.xy.size() >= static_cast<size_t>(std::max(1, m_icp.options().min_good_points));
	if (matchesKeyframePoints() &&
		((placedByMap && m_keyframes.wantsKeyframe(pose)) || overdue || onTime))
		m_keyframes.addKeyframe(pose, scan.points.xy), m_lastKeyframe_s = scan.t_s;
}

void CScanMatchingPoseEstimator::searchWiderIfPoor(const matching::TLineScanFrame& frame, const common::TRangeData& scan,
												   std::optional<matching::TPoseMatch>& icpMatch)
{
	// A match that is good and fits is kept: the search is a recovery, not a
	// competitor (in a room of repeated structure a wide search finds more
	// than one place).
	const bool poor = !icpMatch || icpMatch->quality != matching::EMatchQuality::good ||
					  icpMatch->fit < m_icp.options().restart_below_fit;
	if (!poor) return;
	const auto searched = wideSearchSeed(frame);
	if (!searched) return;
	const auto& o = m_gapSearch.options();
	if (!m_gapSinceMatch && icpMatch)
	{  // where the first match already is, ICP would end there again (aces: 120 of 120 searches)
		const auto d = *searched - icpMatch->pose;
		if (d.norm() < o.slip_same_basin_m && std::abs(mrpt::math::wrapToPi(d.phi())) < o.slip_same_basin_rad) return;
	}
	std::vector<matching::TPoseMatch> results;
	const auto recovered = runIcp(frame, scan, {*searched}, false, results);
	// the scan must clearly prefer the searched pose (csail from entry 400:
	// a first match 0.02 m off fitting 0.603, the searched one 0.7 m off 0.617)
	if (recovered && recovered->quality != matching::EMatchQuality::failed &&
		(!icpMatch || recovered->fit >= icpMatch->fit + o.min_fit_gain))
		icpMatch = recovered;
}

std::vector<mrpt::math::TPoint2D> CScanMatchingPoseEstimator::pointsTheReferenceHolds(
	const std::vector<mrpt::math::TPoint2D>& points, const mrpt::poses::CPose2D& pose, double maxDistance_m)
{
	// A feature the keyframes do not hold yet (a door recess coming into
	// reach) cannot constrain the match: laser-only building, 8 m scanner,
	// t = 175 s, a recess new at the edge of reach held 1.4-2.9 % of the
	// scan's information while the matches held the estimate for 2.4 s.
	if (m_keyframes.empty()) return points;
	const matching::CPointIndex2D& reference = m_keyframes.referenceIndex(pose);
	std::vector<mrpt::math::TPoint2D> held;
	held.reserve(points.size());
	uint32_t index = 0;
	float distance2 = 0;
	for (const auto& p : points)
	{
		const auto w = pose + p;
		if (reference.nearest(static_cast<float>(w.x), static_cast<float>(w.y), 1, &index, &distance2) > 0 &&
			distance2 <= maxDistance_m * maxDistance_m)
			held.push_back(p);
	}
	return held;
}

bool CScanMatchingPoseEstimator::priorHoldsLooseAxes() const
{
	// While stalled the constant-velocity prior is all there is along a
	// direction the scan's surfaces do not constrain (a bare corridor's
	// axis beyond the scanner's reach): ICP's own covariance claimed a few
	// centimetres there, the matches held the estimate on the last keyframe
	// and the velocity measured from those estimates fell to zero
	// (laser-only building, 8 m scanner: 5.7 m of travel lost in 10 s).
	if (m_stalledSinceMatch) return true;
	// So it is in a log without odometry, its readings never moving
	// (unconstrained_axis_without_odometry): aces without odometry, t =
	// 154-178 s, the estimate stood while the robot drove 8 m down a
	// corridor. Not for readings that froze after moving (intel frozen at
	// 0.8 of its scans: 0.17 -> 1.14 m).
	if (m_options.unconstrained_axis_without_odometry && m_readingsOverruledSinceMatch && !m_odometryHasMoved)
		return true;
	// And after lost readings (unconstrained_axis_after_gap), once a
	// velocity was measured: the long corridor at a scan per second,
	// readings lost for 10 s at 1 m/s (not a loss "at speed" by
	// max_decel_mps2: 1 m/s is shed in 0.5 s), stood still through the
	// fault. Not at a log's first scans, where no velocity is known (aces
	// cut at entry 50: ATE 0.092 -> 0.158 m).
	if (m_options.unconstrained_axis_after_gap && m_lostReadingsSinceMatch && m_motion.velocityKnown()) return true;
	// And after readings that froze after motion (unconstrained_axis_after_freeze):
	// the same corridor with the readings frozen for 10 s, 3.70 m. Not
	// for a log's first readings at rest (froze_after_motion): the
	// corridor with creeping readings then never started down the axis.
	return m_options.unconstrained_axis_after_freeze && m_frozenReadingsSinceMatch && m_motion.velocityKnown();
}

void CScanMatchingPoseEstimator::leaveUnconstrainedAxisToPrior(matching::TPoseMatch& match,
																 const matching::TLineScanFrame& frame)
{
	const double maxFraction = m_options.stalled_unconstrained_max_fraction;
	if (maxFraction <= 0 || !priorHoldsLooseAxes()) return;
	const auto& geometric = m_icp.options().geometric;
	const matching::TScanConstraint c = matching::scanTranslationConstraint(
		pointsTheReferenceHolds(frame.points, match.pose, geometric.max_match_distance_m),
		m_options.stalled_normal_radius_m, geometric.full_weight_spacing_m);
	constexpr size_t kMinSurfacePoints = 10;  // fewer: too little of a scan to judge (as in icp_covariance)
	if (c.points < kMinSurfacePoints || c.weakest_fraction >= maxFraction) return;
	const double c0 = std::cos(match.pose.phi()), s0 = std::sin(match.pose.phi());
	const Eigen::Vector2d d(c0 * c.weakest.x() - s0 * c.weakest.y(), s0 * c.weakest.x() + c0 * c.weakest.y());  // world
	match.covariance.topLeftCorner<2, 2>() += geometric.max_std_m * geometric.max_std_m * d * d.transpose();
}

std::optional<mrpt::poses::CPose2D> CScanMatchingPoseEstimator::wideSearchSeed(const matching::TLineScanFrame& frame)
{
	// After a gap, only while the motion since the last match is unknown: a
	// velocity held through a fault at speed is a prediction (CMotionPrior
	// max_decel_mps2), and down a corridor a search would find any place
	// along the axis. With odometry, a heading slip beyond its model
	// ([gap_search] after_poor_match).
	if ((m_gapSinceMatch && m_gapVelocityMeasured) || !m_previousFrame || !m_ukf.hasClone()) return std::nullopt;
	// odometry that never moved has no slip: a robot at rest, or a log
	// without odometry before its zeros count as frozen (laser-only csail
	// from its first scan: a searched turn the filter refused against their
	// zero motion moved the run from 1.8 to 6.5 m); zeros after motion may
	// be readings that froze, and are searched
	if (!m_gapSinceMatch && !m_odometryHasMoved) return std::nullopt;
	const auto window =
		m_gapSinceMatch ? m_gapSearch.windowFor(m_priorCovSinceMatch) : m_gapSearch.slipWindowFor(m_sinceMatchCov);
	if (!window) return std::nullopt;
	common::CStageTimer::CScope t(m_timer, "gap_search");
	const mrpt::poses::CPose2D clonePose = toPose(m_ukf.clonePose());
	const auto relative = m_gapSearch.search(m_previousFrame->pointsMap, frame.pointsMap, currentPose() - clonePose, *window,
											 m_gapSinceMatch ? ESearchKind::after_gap : ESearchKind::after_poor_match);
	if (!relative) return std::nullopt;
	return clonePose + *relative;
}

bool CScanMatchingPoseEstimator::widenRefutedPrediction(const matching::TPoseMatch& match, const Eigen::Matrix3d& R,
														const std::function<double()>& predictionFit)
{
	const TUkfSectionOptions& o = m_ukfOptions;
	if (!predictionFit || o.refuted_prediction_min_fit <= 0 || match.fit < o.refuted_prediction_min_fit) return false;
	// Only a match that pins the translation down can refute the prediction:
	// a short-range scanner in an open hall (sim-open-hall.ini with a 5.6 m
	// Hokuyo URG) sees two pillars and a crate corner, which fit somewhere
	// else 10 m and 120 deg away as well (ATE 9.9 m against odometry's 0.78).
	if (!m_motion.constrainsTranslation(match.covariance)) return false;
	const double nis = m_ukf.absoluteNis(toVec(match.pose), R);
	if (!(nis > o.gate_nis) || match.fit - predictionFit() < o.refuted_prediction_min_fit_gain) return false;
	// csail from entry 0, t = 19 s: odometry turned 6 deg where the robot
	// turned 28 (it had turned 45 for 25 at the step before: heading noise
	// at fast turns is heavy-tailed); the match fit 0.78, the scan at the
	// prediction 0.20, NIS 57 against the gate of 50.
	m_ukf.inflateCurrentPoseCovariance(2.0 * nis / o.gate_nis);
	return true;
}

void CScanMatchingPoseEstimator::fuse(const matching::TPoseMatch& match, bool relative,
									  fusion::CAdaptiveMeasurementNoise& noise, TPoseEstimate& estimate,
									  const matching::TPoseMatch* refusedTrack, const std::function<double()>& predictionFit)
{
	common::CStageTimer::CScope t(m_timer, "ukf");
	const bool weak = match.quality == matching::EMatchQuality::weak;
	const Eigen::Matrix3d R = noise.effectiveCovariance(match.covariance, weak);
	// A match widened over competing basins (competing_basins.h) is judged
	// by the motion prior in its own basin: whether the scan's best
	// explanation contradicts odometry is what counts refusals (the
	// laser-only sample from entry 50: 0.08 m, 3.79 m if the widened match
	// counted neither way). It says nothing about the matcher's calibration.
	const bool inBasin = match.basin_covariance.has_value() && !relative;
	const double basinNis =
		inBasin ? m_ukf.absoluteNis(toVec(match.pose), noise.effectiveCovariance(*match.basin_covariance, weak)) : 0.0;
	if (!relative && !weak && !inBasin && !refusedTrack) widenRefutedPrediction(match, R, predictionFit);
	const double gate = weak && !relative ? std::min(m_ukfOptions.weak_gate_nis, m_ukfOptions.gate_nis)
										  : m_ukfOptions.gate_nis;
	const auto result = relative ? m_ukf.updateRelative(toVec(match.pose), R, gate)
								 : m_ukf.updateAbsolute(toVec(match.pose), R, gate);
	if (!relative && !weak)
	{
		// The scan fits the refused matches' track about as well as the
		// prediction's: no confirmation of the prediction, and the refused
		// track goes on (laser-only sample from entry 200: the stuck result
		// fitted the only keyframe better and reset the count, 1.80 m).
		if (refusedTrack)
			m_motion.observeMatch(refusedTrack->pose, refusedTrack->covariance, false,
								  std::numeric_limits<double>::infinity(), m_matchTime_s);
		else if (inBasin)
			m_motion.observeMatch(match.pose, *match.basin_covariance, basinNis <= m_ukfOptions.gate_nis, basinNis,
								  m_matchTime_s);
		else
			m_motion.observeMatch(match.pose, match.covariance, result.accepted, result.nis, m_matchTime_s);
	}
	if (result.accepted && !inBasin) noise.observeNis(result.nis);
	estimate.match_method = match.method;
	estimate.match_quality = match.quality;
	estimate.match_accepted = result.accepted;
	estimate.match_nis = result.nis;
}

bool CScanMatchingPoseEstimator::fitsWorseThanPrediction(double fit, const std::function<double()>& predictionFit) const
{
	// The corridor with a 30 m scanner (stress matrix "far"): from a seed
	// 2.5 cm off, ICP ended 0.58 m along the axis, where six far points 17-29
	// m ahead fell next to reference samples (one beam spacing on) and
	// paired, while the near ones by a door recess moved 1 -> 5-8 cm off:
	// more pairs, a worse fit (0.850; the prediction's about 0.9), a few cm
	// of claimed std, NIS 49.9 under the gate of 50.
	if (m_options.max_fit_loss_vs_prediction < 0 || !predictionFit || fit <= 0) return false;
	return predictionFit() - fit > m_options.max_fit_loss_vs_prediction;
}

bool CScanMatchingPoseEstimator::lineFitsWorseThanPrediction(const matching::TPoseMatch& lineMatch,
																 const matching::TLineScanFrame& frame,
																 const std::function<double()>& predictionFit)
{
	const mrpt::poses::CPose2D pose = toPose(m_ukf.clonePose()) + lineMatch.pose;
	return fitsWorseThanPrediction(icpForThisMatch().fit(m_keyframes.referenceIndex(pose), frame.pointsMap, pose),
								   predictionFit);
}

bool CScanMatchingPoseEstimator::wantsIcp(const std::optional<matching::TPoseMatch>& lineMatch) const
{
	using matching::EMatchQuality;
	const bool lineUsable = lineMatch && lineMatch->quality != EMatchQuality::failed;
	// A failed line match leaves this scan unmeasured: ICP runs even before
	// it is due (intel t = 2414.98 s: odometry claimed no turn over 0.27 m,
	// the lines failed, the robot had turned 8 deg, kept until the next ICP).
	const bool lineFailed = lineMatch && !lineUsable;
	// A keyframe due here is placed by ICP (keyframes_after_icp_only), at the
	// keyframes' own spacing rather than at the next ICP step's.
	const bool keyframeDue = m_options.keyframes_after_icp_only && matchesKeyframePoints() &&
							 m_keyframes.wantsKeyframe(currentPose());
	return usesIcp() && (dueForIcp() || lineFailed || keyframeDue) &&
		   (m_options.method == "icp" || m_options.icp_always || !lineUsable ||
			lineMatch->quality == EMatchQuality::weak);
}

void CScanMatchingPoseEstimator::matchAndFuse(matching::TLineScanFrame& frame, const common::TRangeData& scan,
											  TPoseEstimate& estimate)
{
	using matching::EMatchQuality;
	std::optional<matching::TPoseMatch> lineMatch;
	if (usesLines() && m_previousFrame)
	{
		common::CStageTimer::CScope t(m_timer, "line_matching");
		lineMatch = m_lineMatcher.match(*m_previousFrame, frame, m_sinceMatch, m_sinceMatchCov);
	}
	const bool lineUsable = lineMatch && lineMatch->quality != EMatchQuality::failed;
	const bool wantIcp = wantsIcp(lineMatch);
	std::optional<matching::TPoseMatch> icpMatch;
	std::vector<matching::TPoseMatch> icpResults;  // one per seed run
	const matching::TPoseMatch* refusedTrack = nullptr;  // its result, when it competes with the chosen one
	if (wantIcp)
	{
		// Seed: the line result composed onto the previous pose, else the UKF prediction.
		const mrpt::poses::CPose2D clonePose = m_ukf.hasClone() ? toPose(m_ukf.clonePose()) : currentPose();
		// Seeds: the line result first, then the UKF prediction if it differs
		// (a wrong line pairing, e.g. when odometry is missing, must not
		// decide the basin ICP converges in).
		std::vector<mrpt::poses::CPose2D> seeds;
		if (lineUsable) seeds.push_back(clonePose + lineMatch->pose);
		addSeedIfNew(seeds, currentPose());
		// Where the matches the filter keeps refusing put the robot
		// (CMotionPrior); its result is the refused track's only when it is a
		// seed of its own. Taking the next seed's (the standstill seed's)
		// counted a refusal and measured the velocity: laser-only aces from
		// entry 250, t = 967 s, 0.76 -> 0.13 m/s, and the corridor's alias
		// 0.84 m back won next.
		const auto refused = m_motion.contradictedMatchSeed(m_matchTime_s);
		std::optional<size_t> refusedSeed;
		if (m_options.seed_refused_matches && refused && addSeedIfNew(seeds, *refused)) refusedSeed = seeds.size() - 1;
		if (m_options.standstill_seed_after_gap && m_gapSinceMatch && m_ukf.hasClone())
			addSeedIfNew(seeds, clonePose);
		// in a log without odometry, also where the velocity's translation alone carries the robot
		if (m_options.straight_seed_without_odometry && m_gapSinceMatch && !m_odometryHasMoved && m_ukf.hasClone())
			addSeedIfNew(seeds, clonePose + mrpt::poses::CPose2D(m_sinceMatch.x(), m_sinceMatch.y(), 0));
		icpMatch = runIcp(frame, scan, seeds, !refused && estimate.motion_prior.empty(), icpResults);
		searchWiderIfPoor(frame, scan, icpMatch);
		if (icpMatch) leaveUnconstrainedAxisToPrior(*icpMatch, frame);
		if (icpMatch && refusedSeed && *refusedSeed < icpResults.size() &&
			matching::competesWith(*icpMatch, icpResults[*refusedSeed], m_icp.options().competing))
			refusedTrack = &icpResults[*refusedSeed];
		m_sinceIcp = mrpt::poses::CPose2D();
		m_lastIcp_s = m_matchTime_s;
	}
	estimate.matched = lineMatch.has_value() || icpMatch.has_value();
	fuseChosenMatch(frame, lineMatch, icpMatch, refusedTrack, estimate);
}

void CScanMatchingPoseEstimator::fuseChosenMatch(const matching::TLineScanFrame& frame,
												 const std::optional<matching::TPoseMatch>& lineMatch,
												 std::optional<matching::TPoseMatch>& icpMatch,
												 const matching::TPoseMatch* refusedTrack, TPoseEstimate& estimate)
{
	using matching::EMatchQuality;
	std::optional<double> predictionFitValue;  // computed once, when first asked for
	const auto predictionFit = [&]
	{
		if (!predictionFitValue)
		{
			const mrpt::poses::CPose2D predicted = currentPose();
			predictionFitValue = icpForThisMatch().fit(m_keyframes.referenceIndex(predicted), frame.pointsMap, predicted);
		}
		return *predictionFitValue;
	};
	const bool pointMap = matchesKeyframePoints() && !m_keyframes.empty();
	const std::function<double()> fitOfPrediction = pointMap ? std::function<double()>(predictionFit) : nullptr;
	// the prediction fits better than the ICP match: the line match stands in only if it does not fit worse either
	const bool predictionFitsBetter = icpMatch && icpMatch->quality != EMatchQuality::failed &&
									  fitsWorseThanPrediction(icpMatch->fit, fitOfPrediction);
	if (predictionFitsBetter) icpMatch->quality = EMatchQuality::failed;
	if (icpMatch && icpMatch->quality != EMatchQuality::failed)
		fuse(*icpMatch, false, m_icpNoise, estimate, refusedTrack, fitOfPrediction);
	else if (lineMatch && lineMatch->quality != EMatchQuality::failed && m_ukf.hasClone() &&
			 (!predictionFitsBetter || !lineFitsWorseThanPrediction(*lineMatch, frame, fitOfPrediction)))
		fuse(*lineMatch, true, m_lineNoise, estimate);
	else if (icpMatch)
		estimate.match_method = icpMatch->method, estimate.match_quality = EMatchQuality::failed;
	else if (lineMatch)
		estimate.match_method = lineMatch->method, estimate.match_quality = EMatchQuality::failed;
}

TPoseEstimate CScanMatchingPoseEstimator::update(const TOdometryIncrement& increment, const common::TRangeData& all,
												 const std::vector<bool>* excludedBeams)
{
	// People (predicted by the dynamic filter) are left out of line extraction and ICP.
	const bool anyExcluded = excludedBeams && std::find(excludedBeams->begin(), excludedBeams->end(), true) !=
												  excludedBeams->end();
	const common::TRangeData withoutPeople = anyExcluded ? common::withoutBeams(all, *excludedBeams) : common::TRangeData();
	const common::TRangeData& scan = anyExcluded ? withoutPeople : all;
	TPoseEstimate estimate;
	const TMotionPrior prior = m_motion.prior(increment, scan.t_s);
	estimate.motion_prior = prior.reason;
	if (m_started)
	{
		predict(increment, prior);
		restartAtRefusedMatches(prior, scan.t_s);
	}
	if (!m_started || dueForMatch(scan.t_s))
	{
		m_timedMatch = dueByTime(scan.t_s);  // a timed match checks with ICP too
		m_matchTime_s = scan.t_s;
		matching::TLineScanFrame frame = makeFrame(scan);
		if (m_started) matchAndFuse(frame, scan, estimate);
		m_started = true;
		addKeyframeIfDue(scan, estimate);
		estimate.lines = frame.lines;
		m_previousFrame = std::move(frame);
		m_ukf.cloneCurrentPose();
		m_sinceMatch = mrpt::poses::CPose2D();
		m_sinceMatchCov.setZero();
		m_priorCovSinceMatch.setZero();
		m_gapSinceMatch = false, m_stalledSinceMatch = false, m_readingsOverruledSinceMatch = false;
		m_lostReadingsSinceMatch = false, m_frozenReadingsSinceMatch = false;
	}
	estimate.pose = currentPose();
	estimate.covariance = m_ukf.covariance();
	m_motion.observePose(estimate.pose, scan.t_s);
	return estimate;
}

}  // namespace hslam::slam
