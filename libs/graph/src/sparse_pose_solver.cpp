#include <hslam/graph/sparse_pose_solver.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>

namespace hslam::graph
{
namespace
{
/** Error of one edge and its Jacobians with respect to the two node poses
 * (g2o's / SPA's SE(2) edge: e = t2v(Z^-1 X_i^-1 X_j)). */
struct TEdgeLinearization
{
	Eigen::Vector3d error;
	Eigen::Matrix3d A, B;  //!< d error / d x_i, d error / d x_j
};

TEdgeLinearization linearize(const mrpt::math::TPose2D& xi, const mrpt::math::TPose2D& xj,
							 const mrpt::math::TPose2D& z)
{
	const double ci = std::cos(xi.phi), si = std::sin(xi.phi), cz = std::cos(z.phi), sz = std::sin(z.phi);
	Eigen::Matrix2d RiT, RzT, dRiT;
	RiT << ci, si, -si, ci;
	RzT << cz, sz, -sz, cz;
	dRiT << -si, ci, -ci, -si;
	const Eigen::Vector2d dt(xj.x - xi.x, xj.y - xi.y);
	TEdgeLinearization l;
	l.error.head<2>() = RzT * (RiT * dt - Eigen::Vector2d(z.x, z.y));
	l.error[2] = mrpt::math::wrapToPi(xj.phi - xi.phi - z.phi);
	l.A.setZero(), l.B.setZero();
	l.A.topLeftCorner<2, 2>() = -RzT * RiT;
	l.A.block<2, 1>(0, 2) = RzT * dRiT * dt;
	l.A(2, 2) = -1;
	l.B.topLeftCorner<2, 2>() = RzT * RiT;
	l.B(2, 2) = 1;
	return l;
}

double chi2Of(const std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges)
{
	double sum = 0;
	for (const auto& e : edges)
		if (e.active)
		{
			const Eigen::Vector3d r = linearize(nodes[e.from].pose, nodes[e.to].pose, e.relative).error;
			sum += r.dot(e.information * r);
		}
	return sum;
}

/** Adds a 3x3 block at free-node block (r, c) (node 0 is fixed: no block). */
void addBlock(std::vector<Eigen::Triplet<double>>& t, size_t r, size_t c, const Eigen::Matrix3d& m)
{
	if (r == 0 || c == 0) return;
	for (int i = 0; i < 3; ++i)
		for (int j = 0; j < 3; ++j)
			t.emplace_back(static_cast<int>(3 * (r - 1) + i), static_cast<int>(3 * (c - 1) + j), m(i, j));
}

/** The normal equations H dx = -g of the active edges at the current poses. */
void buildNormalEquations(const std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges,
						  Eigen::SparseMatrix<double>& H, Eigen::VectorXd& g)
{
	const auto n = static_cast<Eigen::Index>(3 * (nodes.size() - 1));
	std::vector<Eigen::Triplet<double>> t;
	t.reserve(36 * edges.size());
	g.setZero(n);
	for (const auto& e : edges)
	{
		if (!e.active) continue;
		const auto l = linearize(nodes[e.from].pose, nodes[e.to].pose, e.relative);
		const Eigen::Matrix3d& W = e.information;
		addBlock(t, e.from, e.from, l.A.transpose() * W * l.A);
		addBlock(t, e.from, e.to, l.A.transpose() * W * l.B);
		addBlock(t, e.to, e.from, l.B.transpose() * W * l.A);
		addBlock(t, e.to, e.to, l.B.transpose() * W * l.B);
		if (e.from > 0) g.segment<3>(3 * static_cast<Eigen::Index>(e.from - 1)) += l.A.transpose() * W * l.error;
		if (e.to > 0) g.segment<3>(3 * static_cast<Eigen::Index>(e.to - 1)) += l.B.transpose() * W * l.error;
	}
	H.resize(n, n);
	H.setFromTriplets(t.begin(), t.end());
}

std::vector<TGraphNode> stepped(const std::vector<TGraphNode>& nodes, const Eigen::VectorXd& dx)
{
	std::vector<TGraphNode> out = nodes;
	for (size_t k = 1; k < out.size(); ++k)
	{
		auto& p = out[k].pose;
		const auto i = static_cast<Eigen::Index>(3 * (k - 1));
		p.x += dx[i], p.y += dx[i + 1], p.phi = mrpt::math::wrapToPi(p.phi + dx[i + 2]);
	}
	return out;
}
}  // namespace

size_t solvePoseGraphSparse(std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges,
							const TSparseSolverOptions& o)
{
	if (nodes.size() < 2) return 0;
	Eigen::SparseMatrix<double> H;
	Eigen::VectorXd g;
	Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
	double chi2 = chi2Of(nodes, edges), lambda = o.initial_lambda;
	size_t iterations = 0;
	for (int it = 0; it < o.max_iterations; ++it)
	{
		++iterations;
		buildNormalEquations(nodes, edges, H, g);
		if (it == 0) ldlt.analyzePattern(H);  // the pattern is the same at every iteration
		for (int retry = 0; retry < 10; ++retry, lambda *= 10)
		{
			Eigen::SparseMatrix<double> damped = H;
			for (Eigen::Index k = 0; k < damped.rows(); ++k)
				damped.coeffRef(k, k) = damped.coeff(k, k) * (1 + lambda) + 1e-12;
			ldlt.factorize(damped);
			if (ldlt.info() != Eigen::Success) continue;
			const Eigen::VectorXd dx = ldlt.solve(-g);
			auto candidate = stepped(nodes, dx);
			const double newChi2 = chi2Of(candidate, edges);
			if (newChi2 > chi2) continue;
			nodes = std::move(candidate);
			const bool converged = chi2 - newChi2 <= o.min_relative_chi2_decrease * chi2 ||
								   dx.lpNorm<Eigen::Infinity>() <= o.min_step;
			chi2 = newChi2, lambda = std::max(lambda / 10, 1e-12);
			if (converged) return iterations;
			break;
		}
		if (lambda > 1e6) break;  // no step lowers chi2: at a minimum
	}
	return iterations;
}

}  // namespace hslam::graph
