/* hslam sim: Pioneer P3-DX differential-drive kinematics with the odometry
 * errors of thesis 4.1 (UMBmark, eq. 23-28).
 *
 * The robot is commanded in (v, w) like the Pioneer's controller: the wheel
 * servos make the ENCODERS count the nominal wheel travel
 *     dL = (v - w b/2) dt,  dR = (v + w b/2) dt     (b = nominal wheelbase 0.335 m).
 * Odometry integrates exactly those counts with the nominal geometry, so it
 * always believes the command was executed. The TRUE motion uses the actual
 * wheels:
 *  - systematic errors (UMBmark): the wheel-diameter ratio Ed = D_R / D_L
 *    (eq. 27's d) with the mean diameter kept (D_L = 2/(Ed+1) D, D_R = 2Ed/(Ed+1) D,
 *    the inverse of the correction factors of eq. 28), and the wheelbase error
 *    Eb = b_actual / b_nominal. A straight command then drives on a circle of
 *    radius R = (b_actual/2)(Ed+1)/(Ed-1) (eq. 27 solved for R), i.e. after a
 *    chord L the heading changed by beta with R = L / (2 sin(beta/2)) (eq. 26);
 *    a nominal 90 deg turn becomes 90/Eb deg (UMBmark type-A error).
 *  - random errors (wheel slip, floor unevenness): each wheel's true travel
 *    gets zero-mean Gaussian noise of variance k_wheel^2 |d_wheel| (so the error
 *    grows with the square root of the distance and of the rotation), plus a
 *    heading noise of variance k_rot^2 |dtheta|.
 * Velocity and acceleration limits of the P3-DX (Aria p3dx-sh.p) clamp the command.
 * The pose update integrates each step exactly along its arc. */
#pragma once

#include <hslam/calib/COdometryCorrection.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/math/TTwist2D.h>

#include <random>

namespace hslam::sim
{
struct TDiffDriveOptions
{
	double wheelbase_m = 0.335;  //!< nominal wheel separation b (thesis 4.1; Pioneer P3-DX)
	double wheel_diameter_m = 0.195;  //!< nominal wheel diameter (P3-DX 195 mm)
	double ed_wheel_diameter_ratio = 1.0;  //!< UMBmark Ed = D_R/D_L (eq. 27 d); 1 = no error
	double eb_wheelbase_ratio = 1.0;  //!< UMBmark Eb = b_actual/b_nominal; 1 = no error
	/** Borenstein's scaling error Es = actual / nominal mean wheel diameter
	 * (worn or under-inflated tyres, a wrong nominal diameter): odometry
	 * over- or under-states every distance by 1/Es. UMBmark does not see it. */
	double es_wheel_scale_ratio = 1.0;
	double wheel_noise_m_per_sqrt_m = 0.0;  //!< k_wheel: std of a wheel's travel error after 1 m
	double rotation_noise_rad_per_sqrt_rad = 0.0;  //!< k_rot: heading std after 1 rad of rotation
	double max_speed_mps = 1.2;  //!< clamp of |v| (P3-DX top speed 1.2 m/s)
	double max_turn_rate_rad_s = 300.0 * M_PI / 180.0;  //!< clamp of |w|
	double max_accel_mps2 = 1.0;  //!< linear acceleration limit (0 = none)
	double max_rot_accel_rad_s2 = 200.0 * M_PI / 180.0;  //!< rotational acceleration limit (0 = none)
	/** UMBmark calibration the ODOMETRY applies to the encoder counts (thesis
	 * 4.1, eq. 25-28); its own INI section [odometry_correction], not in visit(). */
	calib::TOdometryCorrection odometry_correction;

	template <class V>
	void visit(V& v)
	{
		v.real("wheelbase_m", wheelbase_m, 0.1, 2.0);
		v.real("wheel_diameter_m", wheel_diameter_m, 0.01, 1.0);
		v.real("ed_wheel_diameter_ratio", ed_wheel_diameter_ratio, 0.9, 1.1);
		v.real("eb_wheelbase_ratio", eb_wheelbase_ratio, 0.9, 1.1);
		v.real("es_wheel_scale_ratio", es_wheel_scale_ratio, 0.9, 1.1);
		v.real("wheel_noise_m_per_sqrt_m", wheel_noise_m_per_sqrt_m, 0.0, 0.2);
		v.real("rotation_noise_rad_per_sqrt_rad", rotation_noise_rad_per_sqrt_rad, 0.0, 0.5);
		v.real("max_speed_mps", max_speed_mps, 0.01, 2.2);
		v.degrees("max_turn_rate_deg_s", max_turn_rate_rad_s, 1.0, 500.0);
		v.real("max_accel_mps2", max_accel_mps2, 0.0, 10.0);
		v.degrees("max_rot_accel_deg_s2", max_rot_accel_rad_s2, 0.0, 2000.0);
	}
};

/** Radius of the circle a straight command drives on with wheel ratio Ed
 * (eq. 27 solved for R; infinite for Ed = 1). Positive = turns left. */
double umbmarkCurvatureRadius(double ed, double actualWheelbase_m);

class CDiffDriveRobot
{
   public:
	CDiffDriveRobot() : CDiffDriveRobot(TDiffDriveOptions(), mrpt::math::TPose2D()) {}
	CDiffDriveRobot(const TDiffDriveOptions& options, const mrpt::math::TPose2D& start);

	/** Advances dt_s seconds with the commanded velocities (clamped to the limits). */
	void step(double v_mps, double w_rad_s, double dt_s, std::mt19937_64& rng);

	const mrpt::math::TPose2D& truePose() const { return m_true; }
	/** Dead-reckoning pose from the encoders with the nominal geometry (starts at `start`). */
	const mrpt::math::TPose2D& odometryPose() const { return m_odom; }
	/** Velocity the robot believes (from the encoders), robot frame. */
	const mrpt::math::TTwist2D& odometryVelocity() const { return m_velocity; }
	/** Total nominal travel of each wheel (m) as counted by the encoders. */
	double leftWheelTravel_m() const { return m_leftTravel; }
	double rightWheelTravel_m() const { return m_rightTravel; }
	const TDiffDriveOptions& options() const { return m_opts; }

   private:
	TDiffDriveOptions m_opts;
	mrpt::math::TPose2D m_true, m_odom;
	mrpt::math::TTwist2D m_velocity;
	double m_v = 0, m_w = 0;  //!< current (rate-limited) command
	double m_leftTravel = 0, m_rightTravel = 0;
	double m_leftScale = 1, m_rightScale = 1;  //!< true/nominal wheel diameter
	calib::COdometryCorrection m_correction;  //!< applied to the odometry only
};

/** Moves `pose` by (ds along the arc, dtheta) exactly. */
void integrateArc(mrpt::math::TPose2D& pose, double ds_m, double dtheta_rad);

}  // namespace hslam::sim
