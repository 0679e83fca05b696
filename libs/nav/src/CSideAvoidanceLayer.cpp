/* hslam nav: side obstacle avoidance layer (thesis figure 62, appendix A layer4). */
#include <hslam/nav/CSideAvoidanceLayer.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
TSideAvoidanceOutput CSideAvoidanceLayer::evaluate(const std::array<TVirtualSonar, 8>& ring, double v_mps) const
{
	double sL = 0, sR = 0;
	const double top = std::pow(m_opts.max_range_mm, 0.1);
	for (const auto& s : ring)
	{
		const double r_mm = std::min(s.range_m * 1e3, m_opts.max_range_mm);
		const double term = std::max(0.0, top - std::abs(std::sin(s.angle_rad)) * std::pow(r_mm, 0.1));
		(s.angle_rad > 0 ? sL : sR) += term;
	}
	TSideAvoidanceOutput out;
	// Side obstacle nearer than the threshold (only the side-looking directions count).
	const double sideL = std::min(ring[0].range_m, ring[1].range_m) * 1e3;
	const double sideR = std::min(ring[6].range_m, ring[7].range_m) * 1e3;
	if (std::min(sideL, sideR) < m_opts.side_threshold_mm)
	{
		out.subsume = true;
		out.w_rad_s = sideL < sideR ? -m_opts.escape_rate_rad_s : m_opts.escape_rate_rad_s;
		return out;
	}
	if (sL + sR <= 0) return out;
	const double pL = sL / (sL + sR), pR = 1.0 - pL;
	const double w_deg_s = m_opts.gain_deg_per_mm * (pR - pL) * (v_mps * 1e3 + m_opts.speed_offset_mm_s);
	out.w_rad_s = w_deg_s * M_PI / 180.0;
	return out;
}
}  // namespace hslam::nav
