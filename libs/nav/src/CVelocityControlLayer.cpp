/* hslam nav: velocity control layer (thesis eq. 34). */
#include <hslam/nav/CVelocityControlLayer.h>

#include <algorithm>
#include <cmath>

namespace hslam::nav
{
double CVelocityControlLayer::evaluate(const std::array<TVirtualSonar, 8>& ring) const
{
	double f_mm = 0;
	for (const auto& s : ring) f_mm += std::min(s.range_m * 1e3, m_opts.max_range_mm) * std::cos(s.angle_rad);
	return 1e-3 * m_opts.gain_per_s * f_mm;  // eq. 34, mm/s -> m/s
}
}  // namespace hslam::nav
