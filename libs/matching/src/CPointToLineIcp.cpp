/* hslam: point-to-line ICP against the local map (see CPointToLineIcp.h). */
#include <hslam/matching/CPointToLineIcp.h>

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace hslam::matching
{
namespace
{
/** Sums of one Gauss-Newton step at one pose. */
struct TNormalEquations
{
	Eigen::Matrix3d H = Eigen::Matrix3d::Zero();  //!< sum w J J^T in (x, y, theta)
	Eigen::Matrix3d geometry = Eigen::Matrix3d::Zero();  //!< sum J J^T over the matched points (degeneracy)
	Eigen::Vector3d g = Eigen::Vector3d::Zero();  //!< sum w J r
	double cost = 0;  //!< sum of the robust cost over all points (unmatched: the gate's cost)
	double lever2 = 0;  //!< sum of squared lever arms of the matched points
	double inlierResidual2 = 0;
	size_t matched = 0, inliers = 0;
};

double cauchyCost(double r, double c) { return 0.5 * c * c * std::log1p((r / c) * (r / c)); }

/** Sums at `pose` with correspondences within gate_m; the kernel scale follows
 * the gate (coarse to fine: a scale fixed at the final noise level gives the
 * far points of a rotated scan almost no weight and ICP crawls towards the
 * solution, as measured on aces: a 3 deg seed error was only halved). */
TNormalEquations accumulate(const CLocalPointMap& map, const TOrientedPoints& scan,
							const mrpt::poses::CPose2D& pose, double gate_m, const CPointToLineIcp::TOptions& o)
{
	TNormalEquations e;
	const double kernel = std::max(o.kernel_scale_m, gate_m * o.kernel_gate_ratio);
	const double c = std::cos(pose.phi()), s = std::sin(pose.phi());
	const Eigen::Vector2d t(pose.x(), pose.y());
	const double minCos = std::cos(o.max_normal_angle_rad);
	for (size_t k = 0; k < scan.points.size(); ++k)
	{
		const Eigen::Vector2d& p = scan.points[k];
		const Eigen::Vector2d arm(c * p.x() - s * p.y(), s * p.x() + c * p.y());  // R p
		const Eigen::Vector2d q = arm + t;
		const long j = map.nearest(q, gate_m);
		if (j < 0)
		{
			e.cost += cauchyCost(gate_m, kernel);
			continue;
		}
		const Eigen::Vector2d& n = map.normal(static_cast<size_t>(j));
		const Eigen::Vector2d& nq = scan.normals[k];
		if (std::abs(n.x() * (c * nq.x() - s * nq.y()) + n.y() * (s * nq.x() + c * nq.y())) < minCos)
		{
			e.cost += cauchyCost(gate_m, kernel);
			continue;
		}
		const double r = n.dot(q - map.point(static_cast<size_t>(j)));
		const double w = 1.0 / (1.0 + (r / kernel) * (r / kernel));
		const Eigen::Vector3d J(n.x(), n.y(), n.x() * -arm.y() + n.y() * arm.x());
		e.H += w * J * J.transpose();
		e.geometry += J * J.transpose();
		e.g += w * J * r;
		e.cost += cauchyCost(std::min(std::abs(r), gate_m), kernel);
		e.lever2 += arm.squaredNorm();
		++e.matched;
		if (std::abs(r) < o.inlier_distance_m) ++e.inliers, e.inlierResidual2 += r * r;
	}
	return e;
}

/** H in (x, y, L theta) units, so that its eigenvalues count constraining points. */
Eigen::Matrix3d scaled(const Eigen::Matrix3d& H, double L)
{
	const Eigen::Vector3d k(1, 1, 1 / L);
	return k.asDiagonal() * H * k.asDiagonal();
}

/** Gauss-Newton step updating only the directions the scan's geometry
 * constrains (solution remapping). Degeneracy is a property of the geometry
 * (unweighted J J^T: how many matched points constrain a direction), not of
 * the kernel weights, which are all small far from convergence. */
Eigen::Vector3d remappedStep(const TNormalEquations& e, double L, double minEigen, int& degenerate)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> geo(scaled(e.geometry, L));
	Eigen::Matrix<double, 3, Eigen::Dynamic> basis(3, 0);
	degenerate = 0;
	for (int i = 0; i < 3; ++i)
	{
		if (geo.eigenvalues()[i] < minEigen || geo.eigenvalues()[i] <= 1e-12)
		{
			++degenerate;
			continue;
		}
		basis.conservativeResize(3, basis.cols() + 1);
		basis.col(basis.cols() - 1) = geo.eigenvectors().col(i);
	}
	if (basis.cols() == 0) return Eigen::Vector3d::Zero();
	const Eigen::Matrix3d Hs = scaled(e.H, L);
	const Eigen::Vector3d gs(e.g.x(), e.g.y(), e.g.z() / L);
	const Eigen::MatrixXd A = basis.transpose() * Hs * basis;
	const Eigen::VectorXd b = -(basis.transpose() * gs);
	const Eigen::Vector3d step = basis * A.ldlt().solve(b);
	return {step.x(), step.y(), step.z() / L};
}

Eigen::Matrix3d covarianceOf(const TNormalEquations& e, double L, double minEigen, const CPointToLineIcp::TOptions& o)
{
	const double sigma2 = std::max(e.inliers ? e.inlierResidual2 / static_cast<double>(e.inliers) : 0.0,
								   o.min_sigma_m * o.min_sigma_m) * o.correlation_factor;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scaled(e.geometry, L));
	const Eigen::Matrix3d Hs = scaled(e.H, L);
	Eigen::Vector3d variance;
	for (int i = 0; i < 3; ++i)
		variance[i] = eig.eigenvalues()[i] < minEigen || eig.eigenvalues()[i] <= 1e-12
						  ? o.unconstrained_std_m * o.unconstrained_std_m
						  : sigma2 / std::max(eig.eigenvectors().col(i).dot(Hs * eig.eigenvectors().col(i)), 1e-12);
	Eigen::Matrix3d cov = eig.eigenvectors() * variance.asDiagonal() * eig.eigenvectors().transpose();
	const Eigen::Vector3d k(1, 1, 1 / L);  // back to (x, y, theta)
	cov = k.asDiagonal() * cov * k.asDiagonal();
	cov(0, 0) += o.min_xy_std_m * o.min_xy_std_m;
	cov(1, 1) += o.min_xy_std_m * o.min_xy_std_m;
	cov(2, 2) += o.min_theta_std_rad * o.min_theta_std_rad;
	return cov;
}

double leverArm(const TNormalEquations& e) { return e.matched ? std::max(0.5, std::sqrt(e.lever2 / e.matched)) : 1.0; }
}  // namespace

std::pair<double, double> CPointToLineIcp::fitAt(const CLocalPointMap& map, const TOrientedPoints& scan,
												 const mrpt::poses::CPose2D& pose) const
{
	if (scan.points.empty()) return {0.0, 0.0};
	const TNormalEquations e = accumulate(map, scan, pose, m_options.final_gate_m, m_options);
	const double n = static_cast<double>(scan.points.size());
	return {e.inliers / n, e.cost / n};
}

TMapMatch CPointToLineIcp::match(const CLocalPointMap& map, const TOrientedPoints& scan,
								 const mrpt::poses::CPose2D& guess) const
{
	TMapMatch out;
	out.match.method = "map";
	out.match.pose = guess;
	if (map.empty() || scan.points.size() < static_cast<size_t>(m_options.min_points)) return out;
	std::tie(out.inlier_fraction_at_guess, out.cost_at_guess) = fitAt(map, scan, guess);
	mrpt::poses::CPose2D pose = guess;
	double gate = m_options.start_gate_m;
	const double minEigen = m_options.degenerate_min_fraction * static_cast<double>(scan.points.size());
	for (int it = 0; it < m_options.max_iterations; ++it)
	{
		const TNormalEquations e = accumulate(map, scan, pose, gate, m_options);
		if (e.matched < static_cast<size_t>(m_options.min_points)) break;
		const Eigen::Vector3d d = remappedStep(e, leverArm(e), minEigen, out.degenerate_directions);
		pose = mrpt::poses::CPose2D(pose.x() + d.x(), pose.y() + d.y(), mrpt::math::wrapToPi(pose.phi() + d.z()));
		const bool small = std::hypot(d.x(), d.y()) < 1e-4 && std::abs(d.z()) < 1e-5;
		if (small && gate <= m_options.final_gate_m) break;
		gate = std::max(m_options.final_gate_m, gate * m_options.gate_shrink);
	}
	const TNormalEquations e = accumulate(map, scan, pose, m_options.final_gate_m, m_options);
	const double n = static_cast<double>(scan.points.size());
	const double L = leverArm(e);
	remappedStep(e, L, minEigen, out.degenerate_directions);
	out.match.pose = pose;
	out.match.covariance = covarianceOf(e, L, minEigen, m_options);
	out.match.score = e.inliers / n;
	out.match.correspondences = e.matched;
	out.cost = e.cost / n;
	out.rms_residual_m = e.inliers ? std::sqrt(e.inlierResidual2 / e.inliers) : 0.0;
	out.better_than_guess = out.cost <= out.cost_at_guess + 1e-12;
	const bool enough = e.matched >= static_cast<size_t>(m_options.min_points);
	out.match.quality = !enough || out.match.score < m_options.fail_inlier_fraction ? EMatchQuality::failed
						: out.match.score < m_options.weak_inlier_fraction		 ? EMatchQuality::weak
																				   : EMatchQuality::good;
	return out;
}

}  // namespace hslam::matching
