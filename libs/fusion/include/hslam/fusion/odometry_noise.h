/* hslam: covariance of an odometry increment (dx, dy, dtheta in the robot
 * frame), the UKF process noise (thesis 4.5.3 i).
 *
 *   thesis        eq. 78-80 with d = |dx| (m) and a = |dtheta| (rad):
 *                 var(y) = 0.01 d + 0.5 a d, var(x) = 0.5 a d, var(th) = 0.5 a.
 *                 The thesis leaves the units open and found this model
 *                 unstable: var(x) vanishes on straight motion, so the filter
 *                 trusts odometry perfectly along the path. Kept for comparison.
 *   fixed         the thesis' choice: the eq. 78-80 variances of an "average
 *                 change of 10 cm and 5 degrees" for every increment. Only right
 *                 when increments are that size (it is per step, not per metre).
 *   proportional  (default) standard deviations growing linearly with the
 *                 distance and rotation of the increment, plus a floor; right
 *                 at any scan spacing (0.1 m dense logs as well as 1 m thinned
 *                 ones), the shape MRPT's CActionRobotMovement2D "Thrun" model uses.
 */
#pragma once

#include <hslam/fusion/se2.h>

#include <Eigen/Core>

#include <string>

namespace hslam::fusion
{
struct TOdometryNoiseOptions
{
	std::string model = "proportional";  //!< "proportional", "thesis" or "fixed"
	// proportional model: sigma_xy = xy_per_m * d + xy_per_rad * a + min_xy
	//                     sigma_th = th_per_m * d + th_per_rad * a + min_th
	// Defaults cover the worst of the real Pioneer logs (csail: 10-20 deg heading
	// errors over 45 deg turns); a too-small odometry covariance makes the UKF
	// distrust correct scan matches.
	double xy_std_per_m = 0.1;  //!< m of position error per m travelled
	double xy_std_per_rad = 0.02;  //!< m of position error per rad turned
	double theta_std_per_m_rad = 0.05;  //!< rad of heading error per m travelled (~3 deg/m)
	double theta_std_per_rad = 0.2;  //!< rad of heading error per rad turned
	double min_xy_std_m = 0.002;
	double min_theta_std_rad = 0.002;
	// fixed model: the increment size the thesis evaluated eq. 78-80 at
	double fixed_distance_m = 0.1;
	double fixed_rotation_rad = 5.0 * M_PI / 180.0;

	template <class V>
	void visit(V& v)
	{
		v.choice("model", model, {"proportional", "thesis", "fixed"});
		v.real("xy_std_per_m", xy_std_per_m, 0.0, 2.0);
		v.real("xy_std_per_rad", xy_std_per_rad, 0.0, 2.0);
		v.real("theta_std_per_m_rad", theta_std_per_m_rad, 0.0, 2.0);
		v.real("theta_std_per_rad", theta_std_per_rad, 0.0, 2.0);
		v.real("min_xy_std_m", min_xy_std_m, 1e-6, 1.0);
		v.real("min_theta_std_rad", min_theta_std_rad, 1e-6, 1.0);
		v.real("fixed_distance_m", fixed_distance_m, 0.0, 10.0);
		v.degrees("fixed_rotation_deg", fixed_rotation_rad, 0.0, 180.0);
	}
};

/** Covariance of the increment `delta` (robot frame) under `options`. */
Eigen::Matrix3d odometryIncrementCovariance(const TOdometryNoiseOptions& options, const TPoseVec& delta);

}  // namespace hslam::fusion
