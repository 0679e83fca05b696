/* hslam sim: CDiffDriveRobot (thesis 4.1, UMBmark eq. 23-28). */
#include <hslam/sim/CDiffDriveRobot.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::sim
{
double umbmarkCurvatureRadius(double ed, double actualWheelbase_m)
{
	if (ed == 1.0) return std::numeric_limits<double>::infinity();
	return 0.5 * actualWheelbase_m * (ed + 1.0) / (ed - 1.0);
}

void integrateArc(mrpt::math::TPose2D& pose, double ds, double dth)
{
	// Exact for a constant-curvature step: chord of length 2 (ds/dth) sin(dth/2)
	// in the direction of the mean heading.
	const double chord = std::abs(dth) > 1e-9 ? 2.0 * ds / dth * std::sin(0.5 * dth) : ds;
	const double heading = pose.phi + 0.5 * dth;
	pose.x += chord * std::cos(heading);
	pose.y += chord * std::sin(heading);
	pose.phi = mrpt::math::wrapToPi(pose.phi + dth);
}

CDiffDriveRobot::CDiffDriveRobot(const TDiffDriveOptions& options, const mrpt::math::TPose2D& start)
	: m_opts(options), m_true(start), m_odom(start), m_correction(options.odometry_correction)
{
	const double ed = m_opts.ed_wheel_diameter_ratio;
	const double es = m_opts.es_wheel_scale_ratio;
	m_leftScale = es * 2.0 / (ed + 1.0);
	m_rightScale = es * 2.0 * ed / (ed + 1.0);
}

namespace
{
double limitRate(double current, double target, double maxRate, double dt)
{
	if (maxRate <= 0) return target;
	const double maxDelta = maxRate * dt;
	return current + std::clamp(target - current, -maxDelta, maxDelta);
}
}  // namespace

void CDiffDriveRobot::step(double v_cmd, double w_cmd, double dt, std::mt19937_64& rng)
{
	if (!(dt > 0)) return;
	v_cmd = std::clamp(v_cmd, -m_opts.max_speed_mps, m_opts.max_speed_mps);
	w_cmd = std::clamp(w_cmd, -m_opts.max_turn_rate_rad_s, m_opts.max_turn_rate_rad_s);
	m_v = limitRate(m_v, v_cmd, m_opts.max_accel_mps2, dt);
	m_w = limitRate(m_w, w_cmd, m_opts.max_rot_accel_rad_s2, dt);

	const double b = m_opts.wheelbase_m;
	const double dL = (m_v - 0.5 * m_w * b) * dt;  // encoder (nominal) travel
	const double dR = (m_v + 0.5 * m_w * b) * dt;
	m_leftTravel += dL;
	m_rightTravel += dR;
	double odoDs = 0, odoDth = 0;  // what the (possibly calibrated) odometry makes of the counts
	m_correction.correctWheelTravel(dL, dR, odoDs, odoDth);
	integrateArc(m_odom, odoDs, odoDth);
	m_velocity = m_correction.active() ? mrpt::math::TTwist2D{odoDs / dt, 0.0, odoDth / dt}
									   : mrpt::math::TTwist2D{m_v, 0.0, m_w};

	// True motion: actual wheel diameters and wheelbase, plus random slip.
	double tL = dL * m_leftScale, tR = dR * m_rightScale;
	std::normal_distribution<double> gauss(0.0, 1.0);
	const double k = m_opts.wheel_noise_m_per_sqrt_m;
	if (k > 0)
	{
		tL += k * std::sqrt(std::abs(dL)) * gauss(rng);
		tR += k * std::sqrt(std::abs(dR)) * gauss(rng);
	}
	const double bTrue = b * m_opts.eb_wheelbase_ratio;
	double dth = (tR - tL) / bTrue;
	if (m_opts.rotation_noise_rad_per_sqrt_rad > 0)
		dth += m_opts.rotation_noise_rad_per_sqrt_rad * std::sqrt(std::abs(dth)) * gauss(rng);
	integrateArc(m_true, 0.5 * (tL + tR), dth);
}

}  // namespace hslam::sim
