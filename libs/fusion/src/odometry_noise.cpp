#include <hslam/fusion/odometry_noise.h>

#include <cmath>

namespace hslam::fusion
{
namespace
{
/** Thesis eq. 78-80, d in m, a in rad (diagonal: the thesis states x and y independent). */
Eigen::Vector3d thesisVariances(double d, double a)
{
	return {0.5 * a * d, 0.01 * d + 0.5 * a * d, 0.5 * a};
}
}  // namespace

Eigen::Matrix3d odometryIncrementCovariance(const TOdometryNoiseOptions& o, const TPoseVec& delta)
{
	const double d = std::hypot(delta[0], delta[1]);
	const double a = std::abs(delta[2]);
	const Eigen::Vector3d floor(o.min_xy_std_m * o.min_xy_std_m, o.min_xy_std_m * o.min_xy_std_m,
								o.min_theta_std_rad * o.min_theta_std_rad);
	Eigen::Vector3d var;
	if (o.model == "thesis")
		var = thesisVariances(d, a) + floor;
	else if (o.model == "fixed")
		var = thesisVariances(o.fixed_distance_m, o.fixed_rotation_rad) + floor;
	else
	{
		const double sxy = o.xy_std_per_m * d + o.xy_std_per_rad * a + o.min_xy_std_m;
		const double sth = o.theta_std_per_m_rad * d + o.theta_std_per_rad * a + o.min_theta_std_rad;
		var = {sxy * sxy, sxy * sxy, sth * sth};
	}
	return var.asDiagonal();
}

}  // namespace hslam::fusion
