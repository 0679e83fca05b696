#include <hslam/calib/COdometryScaleCheck.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <limits>

namespace hslam::calib
{
void COdometryScaleCheck::observe(const mrpt::poses::CPose2D& odometry, const mrpt::poses::CPose2D& matched)
{
	if (!m_opts.enabled) return;
	// Intervals are joined until they hold enough motion to be a sample: at 5
	// Hz one interval is 0.1-0.2 m and a few degrees.
	m_forDistance.odometry = m_forDistance.odometry + odometry, m_forDistance.matched = m_forDistance.matched + matched;
	m_forTurn.odometry = m_forTurn.odometry + odometry, m_forTurn.matched = m_forTurn.matched + matched;
	const mrpt::poses::CPose2D& m = m_forDistance.matched;
	const double matched_m = std::hypot(m.x(), m.y());
	if (matched_m >= m_opts.sample_distance_m)
	{
		// the odometry's distance, negative where it ran against the matched motion
		const mrpt::poses::CPose2D& o = m_forDistance.odometry;
		const double odometry_m = std::hypot(o.x(), o.y());
		addSample(m_distance, m_distanceSamples, o.x() * m.x() + o.y() * m.y() < 0 ? -odometry_m : odometry_m, matched_m);
		m_forDistance = {};
	}
	const double matchedTurn = mrpt::math::wrapToPi(m_forTurn.matched.phi());
	if (std::abs(matchedTurn) >= m_opts.sample_turn_rad)
	{
		const double odometryTurn = mrpt::math::wrapToPi(m_forTurn.odometry.phi());
		addSample(m_turn, m_turnSamples, matchedTurn < 0 ? -odometryTurn : odometryTurn, std::abs(matchedTurn));
		m_forTurn = {};
	}
	else if (std::hypot(m_forTurn.matched.x(), m_forTurn.matched.y()) > kMaxTurnSampleTravel_m)
		m_forTurn = {};  // a turn spread over a long drive is the heading's drift, not a turn
}

void COdometryScaleCheck::addSample(TOdometryScaleFit& fit, std::vector<TSample>& samples, double odometry, double matched)
{
	if (odometry == 0) return;  // exact zeros hold no scale (readings that never moved)
	samples.push_back({odometry, matched});
	fit.samples = samples.size();
	if (samples.size() < static_cast<size_t>(m_opts.min_samples)) return;
	// log ratios; a sample whose odometry ran the other way sorts above every ratio
	// (it can only push the median up, and never agrees)
	std::vector<double> logRatios;
	logRatios.reserve(samples.size());
	for (const auto& s : samples)
		logRatios.push_back(s.odometry > 0 ? std::log(s.odometry / s.matched) : std::numeric_limits<double>::infinity());
	std::vector<double> sorted = logRatios;
	const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2);
	std::nth_element(sorted.begin(), mid, sorted.end());
	const double median = *mid;
	if (!std::isfinite(median)) return;
	fit.median_ratio = std::exp(median);
	if (!fit.applied && (std::abs(median) < std::log(m_opts.min_scale_factor) ||
						 std::abs(median) > std::log(m_opts.max_scale_factor)))
		return;
	// the scale: matched over odometric motion summed over the samples that agree with the median
	const double within = std::log(m_opts.consistent_within_factor);
	double sumOdometry = 0, sumMatched = 0;
	size_t agreeing = 0;
	for (size_t i = 0; i < samples.size(); ++i)
		if (std::abs(logRatios[i] - median) <= within)
			sumOdometry += samples[i].odometry, sumMatched += samples[i].matched, ++agreeing;
	if (static_cast<double>(agreeing) < m_opts.min_consistent_fraction * static_cast<double>(samples.size())) return;
	fit.scale = sumMatched / sumOdometry;
	fit.applied = true;
}

bool COdometryScaleCheck::applying() const
{
	// Both quantities must have been judged: a creeping driver scales both,
	// and where the turns were not yet measured (a long straight start) a
	// rescaled distance with turns still at 1 % drove the estimate straight
	// past every corner (simulated floor at a scan per second: 7.0 -> 41 m).
	const size_t n = static_cast<size_t>(m_opts.min_samples);
	if (!(m_distance.applied || m_turn.applied) || m_distance.samples < n || m_turn.samples < n) return false;
	// Readings too coarse once rescaled: the laser-only sample's readings
	// creep at 1 % in ARCOS units (4096 per turn); rescaled by 100 they turn
	// in 8.8 deg steps, and trusted as odometry took the run from 0.05 to
	// 0.32 m
	return !m_turn.applied || m_turn.scale * m_turnStep_rad <= m_opts.max_rescaled_turn_step_rad;
}

void COdometryScaleCheck::noteIncrement(const mrpt::poses::CPose2D& increment)
{
	const double turn = std::abs(mrpt::math::wrapToPi(increment.phi()));
	if (turn > 0 && (m_turnStep_rad == 0 || turn < m_turnStep_rad)) m_turnStep_rad = turn;
}

mrpt::math::TPoint2D COdometryScaleCheck::scaleInUse() const
{
	if (!m_opts.rescale || !applying()) return {m_opts.distance_scale, m_opts.turn_scale};
	return {m_distance.applied ? m_distance.scale : m_opts.distance_scale,
			m_turn.applied ? m_turn.scale : m_opts.turn_scale};
}

mrpt::poses::CPose2D COdometryScaleCheck::correct(const mrpt::poses::CPose2D& increment) const
{
	const mrpt::math::TPoint2D k = scaleInUse();
	if (k.x == 1 && k.y == 1) return increment;
	return mrpt::poses::CPose2D(k.x * increment.x(), k.x * increment.y(), k.y * increment.phi());
}

}  // namespace hslam::calib
