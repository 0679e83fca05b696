#include <hslam/calib/COdometryTimeOffset.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::calib
{
COdometryTimeOffset::COdometryTimeOffset(const TOdometryTimeOffsetOptions& options) : m_options(options)
{
	const int half = static_cast<int>(std::lround(m_options.max_offset_s / m_options.offset_step_s));
	m_cost.assign(static_cast<size_t>(2 * half + 1), 0.0);
}

void COdometryTimeOffset::addReading(double stamp_s, const mrpt::poses::CPose2D& pose)
{
	if (!m_options.estimate_offset || !std::isfinite(stamp_s)) return;
	if (!m_readings.empty() && stamp_s <= m_readings.back().first) return;  // out of order: not used
	const double heading = m_readings.empty()
							   ? pose.phi()
							   : m_readings.back().second + mrpt::math::wrapToPi(pose.phi() - m_readings.back().second);
	m_readings.emplace_back(stamp_s, heading);
	if (m_readingCount++ == 0) m_firstReading_s = stamp_s;
	m_lastReading_s = stamp_s;
	scoreReadyPairs();
}

void COdometryTimeOffset::addMatchedHeading(double t_s, double heading_rad)
{
	if (!m_options.estimate_offset) return;
	if (m_lastMatch && t_s > m_lastMatch->first && t_s - m_lastMatch->first <= m_options.max_pair_s)
		m_waiting.push_back({m_lastMatch->first, t_s, mrpt::math::wrapToPi(heading_rad - m_lastMatch->second)});
	m_lastMatch = std::make_pair(t_s, heading_rad);
	scoreReadyPairs();
}

std::optional<double> COdometryTimeOffset::odometryHeadingAt(double stamp_s) const
{
	const auto after = std::lower_bound(m_readings.begin(), m_readings.end(), stamp_s,
										[](const std::pair<double, double>& r, double t) { return r.first < t; });
	if (after == m_readings.end() || after == m_readings.begin()) return std::nullopt;  // not bracketed
	const auto before = after - 1;
	const double f = (stamp_s - before->first) / (after->first - before->first);
	return before->second + f * (after->second - before->second);
}

void COdometryTimeOffset::scoreReadyPairs()
{
	const int half = static_cast<int>(m_cost.size() / 2);
	const double cap2 = m_options.residual_cap_rad * m_options.residual_cap_rad;
	m_residual2.resize(m_cost.size());
	while (!m_waiting.empty() && !m_readings.empty() &&
		   m_readings.back().first >= m_waiting.front().t2_s + m_options.max_offset_s)
	{
		const TPair p = m_waiting.front();
		m_waiting.pop_front();
		bool complete = true;
		for (int k = -half; k <= half && complete; ++k)
		{
			const double tau = k * m_options.offset_step_s;
			const auto h1 = odometryHeadingAt(p.t1_s + tau), h2 = odometryHeadingAt(p.t2_s + tau);
			if (!h1 || !h2) complete = false;
			else
			{
				const double r = mrpt::math::wrapToPi(p.matchedTurn_rad - (*h2 - *h1));
				m_residual2[static_cast<size_t>(k + half)] = std::min(r * r, cap2);
			}
		}
		if (!complete) continue;  // odometry does not cover every candidate (start, gap)
		for (size_t i = 0; i < m_cost.size(); ++i) m_cost[i] += m_residual2[i];
		m_rotation_rad += std::abs(p.matchedTurn_rad);
		m_pairSpan_s += p.t2_s - p.t1_s;
		++m_pairs;
	}
	// readings older than every pair still to score are not needed
	const double keepFrom =
		(m_waiting.empty() ? (m_lastMatch ? m_lastMatch->first : m_readings.back().first) : m_waiting.front().t1_s) -
		m_options.max_offset_s - 1.0;
	while (m_readings.size() > 2 && m_readings[1].first < keepFrom) m_readings.pop_front();
}

double COdometryTimeOffset::costAt(double offset_s) const
{
	const int half = static_cast<int>(m_cost.size() / 2);
	const double x = std::clamp(offset_s / m_options.offset_step_s + half, 0.0, static_cast<double>(m_cost.size() - 1));
	const size_t i = std::min(static_cast<size_t>(x), m_cost.size() - 2);
	const double f = x - static_cast<double>(i);
	return (1 - f) * m_cost[i] + f * m_cost[i + 1];
}

std::optional<COdometryTimeOffset::TEstimate> COdometryTimeOffset::estimate(double inUse_s) const
{
	if (m_pairs == 0 || m_cost.size() < 3) return std::nullopt;
	const size_t best = static_cast<size_t>(std::min_element(m_cost.begin(), m_cost.end()) - m_cost.begin());
	const int half = static_cast<int>(m_cost.size() / 2);
	double offset = (static_cast<int>(best) - half) * m_options.offset_step_s;
	if (best > 0 && best + 1 < m_cost.size())
	{  // vertex of the parabola through the best candidate and its neighbours
		const double a = m_cost[best - 1], b = m_cost[best], c = m_cost[best + 1], d = a - 2 * b + c;
		if (d > 0) offset += 0.5 * (a - c) / d * m_options.offset_step_s;
	}
	TEstimate e;
	e.offset_s = offset;
	const double inUse = costAt(inUse_s);
	e.cost_ratio = inUse > 0 ? costAt(offset) / inUse : 1.0;
	e.rotation_rad = m_rotation_rad;
	e.pairs = m_pairs;
	const double readingInterval_s =
		m_readingCount > 1 ? (m_lastReading_s - m_firstReading_s) / static_cast<double>(m_readingCount - 1) : 0.0;
	e.readings_per_pair = readingInterval_s > 0 ? m_pairSpan_s / static_cast<double>(m_pairs) / readingInterval_s : 0.0;
	return e;
}

std::optional<double> COdometryTimeOffset::offsetToApply(double inUse_s) const
{
	if (!m_options.estimate_offset || m_rotation_rad < m_options.min_rotation_rad) return std::nullopt;
	const auto e = estimate(inUse_s);
	if (!e || e->readings_per_pair < m_options.min_readings_per_pair || e->cost_ratio > m_options.max_cost_ratio ||
		std::abs(e->offset_s - inUse_s) < m_options.min_change_s)
		return std::nullopt;
	return e->offset_s;
}

}  // namespace hslam::calib
