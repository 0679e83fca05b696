/* hslam nav: corner trap rule (see CCornerTrapDetector.h). */
#include <hslam/nav/CCornerTrapDetector.h>

namespace hslam::nav
{
bool CCornerTrapDetector::looksLikeCorner(const CPolarProfile& p) const
{
	const double d2r = M_PI / 180.0;
	const double left = p.minRange(45 * d2r, 90 * d2r) * 1e3;
	const double right = p.minRange(-90 * d2r, -45 * d2r) * 1e3;
	const double front = p.minRange(-20 * d2r, 20 * d2r) * 1e3;
	return left < m_opts.corner_range_mm && right < m_opts.corner_range_mm && front < m_opts.corner_front_mm;
}

bool CCornerTrapDetector::update(const CPolarProfile& profile)
{
	m_count = looksLikeCorner(profile) ? m_count + 1 : 0;
	return m_count >= m_opts.confirm_steps;
}
}  // namespace hslam::nav
