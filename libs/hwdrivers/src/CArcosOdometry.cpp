/* hslam: ARCOS odometry integration (see CArcosOdometry.h). */
#include <hslam/hwdrivers/CArcosOdometry.h>
#include <mrpt/math/wrap2pi.h>

namespace hslam::hwdrivers
{
int CArcosOdometry::unwrapDelta15(int current, int previous)
{
	int d = current - previous;
	if (d > 0x1000) d -= 0x8000;
	if (d < -0x1000) d += 0x8000;
	return d;
}

void CArcosOdometry::resetToOrigin()
{
	m_initialised = true;
	m_prevX = m_prevY = m_prevTh = 0;
	m_pose = mrpt::poses::CPose2D();
}

void CArcosOdometry::update(const arcos::TSip& sip)
{
	const double mm2m = 1e-3;
	if (!m_initialised)
	{
		const auto signed15 = [](int raw) { return raw >= 0x4000 ? raw - 0x8000 : raw; };
		m_pose = mrpt::poses::CPose2D(signed15(sip.xpos_raw) * m_conv.dist_mm_per_unit * mm2m,
									  signed15(sip.ypos_raw) * m_conv.dist_mm_per_unit * mm2m,
									  mrpt::math::wrapToPi(sip.thpos_raw * m_conv.angle_rad_per_unit));
		m_initialised = true;
	}
	else
	{
		const int dx = unwrapDelta15(sip.xpos_raw, m_prevX);
		const int dy = unwrapDelta15(sip.ypos_raw, m_prevY);
		// Heading counts 4096 units per turn: unwrap in units, then convert.
		int dthUnits = sip.thpos_raw - m_prevTh;
		if (dthUnits > 2048) dthUnits -= 4096;
		if (dthUnits < -2048) dthUnits += 4096;
		const double dth = dthUnits * m_conv.angle_rad_per_unit;
		if (m_correction.active())
		{
			// The controller's increment in its own robot frame, corrected
			// (UMBmark, thesis 4.1), composed onto our pose.
			const double th0 = m_prevTh * m_conv.angle_rad_per_unit;
			const double wx = dx * m_conv.dist_mm_per_unit * mm2m, wy = dy * m_conv.dist_mm_per_unit * mm2m;
			const mrpt::poses::CPose2D local(std::cos(th0) * wx + std::sin(th0) * wy,
											 -std::sin(th0) * wx + std::cos(th0) * wy, dth);
			m_pose = m_pose + m_correction.correctIncrement(local);
		}
		else
		{
			m_pose.x(m_pose.x() + dx * m_conv.dist_mm_per_unit * mm2m);
			m_pose.y(m_pose.y() + dy * m_conv.dist_mm_per_unit * mm2m);
			m_pose.phi(mrpt::math::wrapToPi(m_pose.phi() + dth));
		}
	}
	m_prevX = sip.xpos_raw;
	m_prevY = sip.ypos_raw;
	m_prevTh = sip.thpos_raw;

	m_left_mps = sip.vel_left_raw * m_conv.vel_mms_per_unit * mm2m;
	m_right_mps = sip.vel_right_raw * m_conv.vel_mms_per_unit * mm2m;
	m_vel.vx = 0.5 * (m_left_mps + m_right_mps);
	m_vel.vy = 0;
	m_vel.omega = sip.has_tail ? sip.rotvel_x10 * 0.1 * M_PI / 180.0
							   : 0.5 * (sip.vel_right_raw - sip.vel_left_raw) * m_conv.vel_mms_per_unit *
									 m_conv.diff_conv_per_mm;
}

}  // namespace hslam::hwdrivers
