#include <hslam/graph/sparse_pose_solver.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
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

/** Where the active edges' 3x3 blocks live in H's value array: H's pattern
 * is the same at every iteration of a solve, so it is built once and an
 * iteration only writes numbers (assembling from triplets, which sorts them
 * again each time, was half of a solve). Per active edge and block (from-from,
 * from-to, to-from, to-to), per column j of the block, the value index of
 * the block's first row in that column; -1 for a block of node 0 (fixed). */
struct TBlockSlots
{
	std::array<std::array<Eigen::Index, 3>, 4> first{};
};

/** H's pattern (every value 0) for the active edges, and their slots. */
std::vector<TBlockSlots> patternOf(size_t nodeCount, const std::vector<TGraphEdge>& edges, Eigen::SparseMatrix<double>& H)
{
	const auto n = static_cast<Eigen::Index>(3 * (nodeCount - 1));
	std::vector<Eigen::Triplet<double>> t;
	t.reserve(36 * edges.size());
	const auto blocks = [](const TGraphEdge& e) {
		return std::array<std::pair<size_t, size_t>, 4>{
			{{e.from, e.from}, {e.from, e.to}, {e.to, e.from}, {e.to, e.to}}};
	};
	for (const auto& e : edges)
		if (e.active)
			for (const auto& [r, c] : blocks(e))
				if (r > 0 && c > 0)
					for (int i = 0; i < 3; ++i)
						for (int j = 0; j < 3; ++j)
							t.emplace_back(static_cast<int>(3 * (r - 1) + i), static_cast<int>(3 * (c - 1) + j), 0.0);
	H.resize(n, n);
	H.setFromTriplets(t.begin(), t.end());
	std::vector<TBlockSlots> slots;
	for (const auto& e : edges)
	{
		if (!e.active) continue;
		TBlockSlots s;
		const auto b = blocks(e);
		for (size_t k = 0; k < 4; ++k)
			for (int j = 0; j < 3; ++j)
			{
				s.first[k][static_cast<size_t>(j)] = -1;
				if (b[k].first == 0 || b[k].second == 0) continue;
				const auto col = static_cast<Eigen::Index>(3 * (b[k].second - 1) + static_cast<size_t>(j));
				const auto row = static_cast<int>(3 * (b[k].first - 1));
				const int* begin = H.innerIndexPtr() + H.outerIndexPtr()[col];
				const int* end = H.innerIndexPtr() + H.outerIndexPtr()[col + 1];
				s.first[k][static_cast<size_t>(j)] = std::lower_bound(begin, end, row) - H.innerIndexPtr();
			}
		slots.push_back(s);
	}
	return slots;
}

/** Adds a 3x3 block at its slots (none for a block of node 0). */
void addBlock(double* values, const std::array<Eigen::Index, 3>& first, const Eigen::Matrix3d& m)
{
	for (int j = 0; j < 3; ++j)
	{
		const Eigen::Index at = first[static_cast<size_t>(j)];
		if (at < 0) continue;
		for (int i = 0; i < 3; ++i) values[at + i] += m(i, j);
	}
}

/** The normal equations H dx = -g of the active edges at the current poses,
 * into H's pattern (patternOf). Each entry sums its edges' terms in edge
 * order, as summing triplets did: the same numbers, bit for bit. */
void buildNormalEquations(const std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges,
						  const std::vector<TBlockSlots>& slots, Eigen::SparseMatrix<double>& H, Eigen::VectorXd& g)
{
	std::fill(H.valuePtr(), H.valuePtr() + H.nonZeros(), 0.0);
	g.setZero(H.rows());
	double* values = H.valuePtr();
	size_t k = 0;
	for (const auto& e : edges)
	{
		if (!e.active) continue;
		const auto& s = slots[k++];
		const auto l = linearize(nodes[e.from].pose, nodes[e.to].pose, e.relative);
		const Eigen::Matrix3d& W = e.information;
		addBlock(values, s.first[0], l.A.transpose() * W * l.A);
		addBlock(values, s.first[1], l.A.transpose() * W * l.B);
		addBlock(values, s.first[2], l.B.transpose() * W * l.A);
		addBlock(values, s.first[3], l.B.transpose() * W * l.B);
		if (e.from > 0) g.segment<3>(3 * static_cast<Eigen::Index>(e.from - 1)) += l.A.transpose() * W * l.error;
		if (e.to > 0) g.segment<3>(3 * static_cast<Eigen::Index>(e.to - 1)) += l.B.transpose() * W * l.error;
	}
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
	const std::vector<TBlockSlots> slots = patternOf(nodes.size(), edges, H);
	Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
	double chi2 = chi2Of(nodes, edges), lambda = o.initial_lambda;
	size_t iterations = 0;
	for (int it = 0; it < o.max_iterations; ++it)
	{
		++iterations;
		buildNormalEquations(nodes, edges, slots, H, g);
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
