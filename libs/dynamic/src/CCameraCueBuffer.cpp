#include <hslam/dynamic/CCameraCueBuffer.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::dynamic
{
void CCameraCueBuffer::add(const std::vector<TCameraCue>& cues, double t_s)
{
	while (!m_cues.empty() && m_cues.front().t_s < t_s - m_options.max_age_s) m_cues.pop_front();
	m_cues.insert(m_cues.end(), cues.begin(), cues.end());
}

bool CCameraCueBuffer::supports(double bearing_rad, double t_s) const
{
	for (const auto& c : m_cues)
	{
		if (std::abs(c.t_s - t_s) > m_options.max_age_s) continue;
		// Bearings relative to the range's centre, so a range across +-pi works.
		const double centre = 0.5 * (c.bearing_min_rad + c.bearing_max_rad);
		const double half = 0.5 * (c.bearing_max_rad - c.bearing_min_rad) + m_options.margin_rad;
		if (std::abs(mrpt::math::wrapToPi(bearing_rad - centre)) <= half) return true;
	}
	return false;
}

}  // namespace hslam::dynamic
