/* hslam nav: boundary following out of local minima (see the header). */
#include <hslam/nav/CBoundaryFollowingLayer.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
TBoundaryFollowingOutput CBoundaryFollowingLayer::update(const CPolarProfile& p, double d, bool targetClear, double t)
{
	if (!m_opts.enabled) return {};
	if (!m_started || (!m_following && d < m_best_m - 1e-3 * m_opts.progress_mm))
	{
		m_started = true;
		m_best_m = d;
		m_lastProgress_s = t;
	}
	if (m_following)
	{
		const bool closer = d < m_enter_m - 1e-3 * m_opts.leave_margin_mm;
		if ((closer && targetClear) || t - m_enter_s > m_opts.max_follow_s)
		{
			m_following = false;
			m_best_m = d;
			m_lastProgress_s = t;
			return {};
		}
		return follow(p);
	}
	if (t - m_lastProgress_s < m_opts.stuck_time_s) return {};
	m_following = true;
	m_enter_m = std::min(m_best_m, d);
	m_enter_s = t;
	const double d2r = M_PI / 180.0;
	m_side = p.minRange(20 * d2r, 120 * d2r) <= p.minRange(-120 * d2r, -20 * d2r) ? 1.0 : -1.0;
	return follow(p);
}

TBoundaryFollowingOutput CBoundaryFollowingLayer::follow(const CPolarProfile& p) const
{
	const double d2r = M_PI / 180.0;
	const double want = 1e-3 * m_opts.follow_distance_mm;
	const double front = p.minRange(-30 * d2r, 30 * d2r);
	const double side = m_side > 0 ? p.minRange(30 * d2r, 120 * d2r) : p.minRange(-120 * d2r, -30 * d2r);
	TBoundaryFollowingOutput out;
	out.active = true;
	if (front < 1.2 * want)  // boundary turns in front: turn away from it in place
	{
		out.w_rad_s = -m_side * m_opts.turn_rate_rad_s;
		return out;
	}
	// Keep the boundary at `want` on its side: steer towards it when too far.
	const double err = std::clamp((side - want) / want, -1.0, 1.0);
	out.w_rad_s = m_side * m_opts.turn_rate_rad_s * err;
	out.v_mps = 1e-3 * m_opts.speed_mm_s;
	return out;
}

}  // namespace hslam::nav
