/* hslam: scan-to-local-map matching by point-to-line ICP (Censi's PL-ICP
 * error, Gauss-Newton with a Cauchy kernel), the front-end's matcher
 * (issue: "scan matching that never loses the robot"). It replaces matching
 * against the previous scan only (thesis 4.4.2 iii) by matching against the
 * keyframes around the robot, so errors do not chain, and it knows what the
 * scan does not constrain:
 *
 *  - Degeneracy (Zhang, Kaess and Singh, ICRA 2016, "solution remapping"):
 *    the Gauss-Newton information H = sum w J J^T is decomposed in
 *    (x, y, L*theta) units (L = rms lever arm of the points, so the three
 *    eigenvalues are comparable: each is the weighted number of points that
 *    constrain that direction). Directions with fewer than
 *    degenerate_min_fraction of the points (a corridor's axis, an open hall)
 *    are not updated: the pose keeps the prediction there, and the
 *    covariance says "unknown" (variance unconstrained_std_m^2).
 *  - A match never fits worse than its guess: the robust cost of the final
 *    pose is compared with the cost of the guess under the same
 *    correspondence gate (better_than_guess).
 *  - Covariance: sigma^2 H^-1 on the constrained subspace, with sigma^2 the
 *    mean squared inlier residual times correlation_factor (neighbouring
 *    beams' errors are correlated), plus floors.
 *
 * All points in the robot frame, the pose in the world frame. */
#pragma once

#include <hslam/matching/CLocalPointMap.h>
#include <hslam/matching/match_result.h>

#include <Eigen/Core>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::matching
{
struct TMapMatch
{
	TPoseMatch match;  //!< pose in the world frame; score = inlier fraction
	double inlier_fraction_at_guess = 0;
	double cost_at_guess = 0, cost = 0;  //!< robust cost per point at the guess / at the result
	double rms_residual_m = 0;  //!< of the inliers at the result
	int degenerate_directions = 0;  //!< of 3; 0 = fully constrained
	bool better_than_guess = false;
};

class CPointToLineIcp
{
   public:
	struct TOptions
	{
		int max_iterations = 30;
		double start_gate_m = 0.8;  //!< correspondence gate of the first iteration...
		double final_gate_m = 0.2;  //!< ...shrinking by gate_shrink per iteration to this
		double gate_shrink = 0.7;
		double kernel_scale_m = 0.05;  //!< Cauchy kernel scale (m) at convergence...
		double kernel_gate_ratio = 0.5;  //!< ...and at least this fraction of the current gate
		double inlier_distance_m = 0.1;  //!< a point is an inlier below this point-to-line distance
		double max_normal_angle_rad = 30.0 * M_PI / 180.0;  //!< normals of paired points agree within this
		int min_points = 20;  //!< fewer matched points: failed
		double fail_inlier_fraction = 0.25;  //!< below: failed
		double weak_inlier_fraction = 0.5;  //!< below: weak
		double degenerate_min_fraction = 0.04;  //!< see file comment
		double correlation_factor = 10.0;  //!< points per independent error
		double min_sigma_m = 0.01;  //!< floor of the residual standard deviation
		double unconstrained_std_m = 10.0;  //!< std reported along unconstrained directions (m; rad via L)
		double min_xy_std_m = 0.01;  //!< floors added to the covariance
		double min_theta_std_rad = 0.2 * M_PI / 180.0;

		template <class V>
		void visit(V& v)
		{
			v.integer("max_iterations", max_iterations, 1, 1000);
			v.real("start_gate_m", start_gate_m, 0.01, 10.0);
			v.real("final_gate_m", final_gate_m, 0.01, 10.0);
			v.real("gate_shrink", gate_shrink, 0.1, 1.0);
			v.real("kernel_scale_m", kernel_scale_m, 0.001, 1.0);
			v.real("kernel_gate_ratio", kernel_gate_ratio, 0.0, 10.0);
			v.real("inlier_distance_m", inlier_distance_m, 0.001, 1.0);
			v.degrees("max_normal_angle_deg", max_normal_angle_rad, 1.0, 90.0);
			v.integer("min_points", min_points, 3, 100000);
			v.real("fail_inlier_fraction", fail_inlier_fraction, 0.0, 1.0);
			v.real("weak_inlier_fraction", weak_inlier_fraction, 0.0, 1.0);
			v.real("degenerate_min_fraction", degenerate_min_fraction, 0.0, 1.0);
			v.real("correlation_factor", correlation_factor, 1.0, 1000.0);
			v.real("min_sigma_m", min_sigma_m, 1e-4, 1.0);
			v.real("unconstrained_std_m", unconstrained_std_m, 0.1, 1000.0);
			v.real("min_xy_std_m", min_xy_std_m, 0.0, 1.0);
			v.degrees("min_theta_std_deg", min_theta_std_rad, 0.0, 10.0);
		}
	};

	CPointToLineIcp() : CPointToLineIcp(TOptions()) {}
	explicit CPointToLineIcp(const TOptions& options) : m_options(options) {}
	const TOptions& options() const { return m_options; }

	/** Pose of the robot whose scan gave `scan` (line-like points with
	 * normals, robot frame) in the frame of `map`, starting from `guess`. A
	 * point pairs only with a map point whose normal is within
	 * max_normal_angle_deg of its own (a clutter point next to a wall would
	 * otherwise pull along the wall's normal). */
	TMapMatch match(const CLocalPointMap& map, const TOrientedPoints& scan,
					const mrpt::poses::CPose2D& guess) const;

	/** Inlier fraction and robust cost per point of `scan` at `pose` (final gate). */
	std::pair<double, double> fitAt(const CLocalPointMap& map, const TOrientedPoints& scan,
									const mrpt::poses::CPose2D& pose) const;

   private:
	TOptions m_options;
};

}  // namespace hslam::matching
