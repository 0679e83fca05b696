/* hslam nav: forward turning layer (thesis figure 63, eq. 35-36). */
#include <hslam/nav/CForwardTurningLayer.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::nav
{
double farRangeWeight(double R_mm) { return 0.5 * (1.0 + std::tanh(3.0 * R_mm / 1000.0 - 9.0)); }  // eq. 35

double sideAvoidanceWeight(double R_mm)  // eq. 36 (printed as w_s, meant as w_a)
{
	return std::max(0.0, (160.0 - std::sqrt(std::max(0.0, R_mm))) / 160.0);
}

TForwardTurningOutput CForwardTurningLayer::update(const CPolarProfile& p, const mrpt::math::TPose2D& pose, double t)
{
	TForwardTurningOutput out;
	const bool corner = m_corner.update(p);
	if (!m_active)
	{
		const double front_mm = p.minRange(-m_opts.front_half_angle_rad, m_opts.front_half_angle_rad) * 1e3;
		if (front_mm >= m_opts.front_trigger_mm && !corner) return out;
		m_active = true;
		m_byCorner = corner;
		m_start = pose;
		m_start_s = t;
		// Turn towards the more open half (ranges summed over 0..110 deg each side).
		double left = 0, right = 0;
		for (double a = 0; a <= 110.0 * M_PI / 180.0; a += 5.0 * M_PI / 180.0)
			left += p.minRange(a, a + 0.01), right += p.minRange(-a - 0.01, -a);
		m_direction = left >= right ? 1.0 : -1.0;
	}
	const double rotated = std::abs(mrpt::math::wrapToPi(pose.phi - m_start.phi));
	const double backed_mm = std::hypot(pose.x - m_start.x, pose.y - m_start.y) * 1e3;
	if (rotated >= m_opts.escape_angle_rad || backed_mm >= m_opts.escape_distance_mm ||
		t - m_start_s > m_opts.max_escape_s)
	{
		m_active = false;
		m_corner.reset();
		return out;
	}
	out.escaping = true;
	out.corner = m_byCorner;
	out.v_mps = -1e-3 * m_opts.back_speed_mm_s;
	out.w_rad_s = m_direction * m_opts.escape_rate_rad_s;
	return out;
}
}  // namespace hslam::nav
