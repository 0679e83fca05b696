/* hslam: odometry from ARCOS SIPs with wrap-around of the position counters.
 *
 * ARCOS reports x, y as 15-bit counters (wrap at 32768 units = 32.768 m on a
 * P3-DX) and the heading modulo 4096 units = 2*pi. Like Aria
 * (ArRobot::processMotorPacket) the increment between two SIPs is unwrapped:
 * dx > 0x1000 -> dx - 0x8000, dx < -0x1000 -> dx + 0x8000 (a robot cannot move
 * 4 m in one 100 ms cycle), and the heading increment is normalised to
 * (-pi, pi]. Increments are summed into an unbounded pose, so long runs never
 * jump. Velocities: v = (vl + vr)/2, w from the ROTVEL field when present, else
 * (vr - vl)/2 * DiffConvFactor (Aria). Thesis section 4.1 calibrates the
 * odometry of the same robot; its correction factors belong in TConversion. */
#pragma once

#include <hslam/calib/COdometryCorrection.h>
#include <hslam/hwdrivers/arcos_sip.h>
#include <mrpt/math/TTwist2D.h>
#include <mrpt/poses/CPose2D.h>

#include <string>

namespace hslam::hwdrivers
{
/** Robot-unit conversion factors (Aria params/p3dx-sh.p). */
struct TArcosConversion
{
	double dist_mm_per_unit = 1.0;  //!< DistConvFactor (0.485 on old P2OS p3dx)
	double angle_rad_per_unit = 0.001534;  //!< AngleConvFactor (2*pi/4096)
	double vel_mms_per_unit = 1.0;  //!< VelConvFactor
	double range_mm_per_unit = 1.0;  //!< RangeConvFactor
	double diff_conv_per_mm = 0.0056;  //!< DiffConvFactor: w = (vr - vl)/2 * this [rad/s]
	/** UMBmark calibration (thesis 4.1, hslam-umbmark) applied to each SIP's pose increment. */
	calib::TOdometryCorrection odometry_correction;

	template <class V>
	void visit(V& v)
	{
		v.real("dist_conv_factor", dist_mm_per_unit, 0.01, 10.0);
		v.real("angle_conv_factor", angle_rad_per_unit, 1e-5, 0.1);
		v.real("vel_conv_factor", vel_mms_per_unit, 0.01, 10.0);
		v.real("range_conv_factor", range_mm_per_unit, 0.01, 10.0);
		v.real("diff_conv_factor", diff_conv_per_mm, 1e-4, 0.1);
		odometry_correction.visit(v);
	}
};

class CArcosOdometry
{
   public:
	explicit CArcosOdometry(const TArcosConversion& conv = TArcosConversion()) : m_conv(conv) {}

	/** Forgets the previous SIP: the next one re-initialises the pose. */
	void reset() { m_initialised = false; }

	/** The robot's counters were just zeroed (SETO): start at (0, 0, 0) with
	 * previous raw counters 0, so the first SIP is already an increment. */
	void resetToOrigin();

	/** Integrates one SIP. The first SIP after reset() sets the pose to the
	 * SIP's own (x, y, th), reading the 15-bit counters as signed
	 * (-16.384 m .. +16.383 m), the only unambiguous choice without SETO. */
	void update(const arcos::TSip& sip);

	/** Accumulated pose (x, y in m, phi in (-pi, pi]). */
	const mrpt::poses::CPose2D& pose() const { return m_pose; }

	/** Velocity in the robot frame (vx m/s, omega rad/s). */
	const mrpt::math::TTwist2D& velocityLocal() const { return m_vel; }

	/** Wheel speeds (m/s). */
	double leftWheel_mps() const { return m_left_mps; }
	double rightWheel_mps() const { return m_right_mps; }

	bool initialised() const { return m_initialised; }

	/** Unwraps a 15-bit counter difference (exposed for tests). */
	static int unwrapDelta15(int current, int previous);

   private:
	TArcosConversion m_conv;
	calib::COdometryCorrection m_correction{m_conv.odometry_correction};
	bool m_initialised = false;
	int m_prevX = 0, m_prevY = 0, m_prevTh = 0;
	mrpt::poses::CPose2D m_pose;
	mrpt::math::TTwist2D m_vel;
	double m_left_mps = 0, m_right_mps = 0;
};

}  // namespace hslam::hwdrivers
