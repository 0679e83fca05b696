/* CPoseGraph: optimisation against hand-derived graphs, robust dropping, export. */
#include <gtest/gtest.h>
#include <hslam/graph/CPoseGraph.h>
#include <mrpt/graphs/CNetworkOfPoses.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <iostream>
#include <sstream>

using namespace hslam::graph;
using mrpt::math::TPose2D;

namespace
{
TGraphEdge edge(size_t a, size_t b, TPose2D rel, EEdgeKind kind, double infoScale = 1.0)
{
	TGraphEdge e;
	e.from = a, e.to = b, e.relative = rel, e.kind = kind;
	e.information = Eigen::Matrix3d::Identity() * infoScale;
	return e;
}
}  // namespace

TEST(PoseGraph, ThreeNodesOnALineMatchTheHandSolution)
{
	// x1 - x0 = 1, x2 - x1 = 1, x2 - x0 = 2.3 (unit information), x0 = 0 fixed:
	// minimise (x1-1)^2 + (x2-x1-1)^2 + (x2-2.3)^2 -> 2 x1 - x2 = 0, 2 x2 - x1 = 3.3
	// -> x1 = 1.1, x2 = 2.2.
	CPoseGraph g;
	g.addNode(10, {0, 0, 0});
	g.addNode(11, {1, 0, 0});
	g.addNode(12, {2, 0, 0});
	g.addEdge(edge(0, 1, {1, 0, 0}, EEdgeKind::sequential));
	g.addEdge(edge(1, 2, {1, 0, 0}, EEdgeKind::sequential));
	g.addEdge(edge(0, 2, {2.3, 0, 0}, EEdgeKind::loop));
	const auto r = g.optimize();
	EXPECT_NEAR(g.nodes()[1].pose.x, 1.1, 1e-6);
	EXPECT_NEAR(g.nodes()[2].pose.x, 2.2, 1e-6);
	EXPECT_NEAR(g.nodes()[2].pose.y, 0.0, 1e-9);
	EXPECT_NEAR(r.initial_chi2, 0.09, 1e-9);  // only the loop disagrees by 0.3
	EXPECT_NEAR(r.final_chi2, 3 * 0.01, 1e-6);  // each edge off by 0.1
	EXPECT_TRUE(r.dropped_edges.empty());
}

TEST(PoseGraph, WeightedSquareLoopClosesWithTheLoopEdgeWeighted)
{
	// Four unit sides of a square with a heading error: the closing edge with
	// 4x information pulls node 3 to within a quarter of the residual.
	CPoseGraph g;
	const double turn = M_PI / 2;
	TPose2D p{0, 0, 0};
	g.addNode(0, p);
	for (int i = 1; i <= 3; ++i)
	{
		p = composePose(p, {1, 0, turn + 0.05});
		g.addNode(i, p);
		g.addEdge(edge(i - 1, i, {1, 0, turn + 0.05}, EEdgeKind::sequential));
	}
	// node 3 is truly at (0, 1, -90 deg) seen from node 0: (0, 1, 270 deg)
	g.addEdge(edge(0, 3, {0, 1, -turn}, EEdgeKind::loop, 4.0));
	const double before = g.edgeChi2(3);
	g.optimize();
	EXPECT_LT(g.edgeChi2(3), 0.25 * before);
	EXPECT_NEAR(g.nodes()[3].pose.x, 0.0, 0.1);
	EXPECT_NEAR(g.nodes()[3].pose.y, 1.0, 0.1);
}

TEST(PoseGraph, WrongLoopEdgeIsDroppedAndTheChainKept)
{
	// a 10-node straight chain with strong sequential edges, one correct loop and
	// one wrong loop (3 m off): the wrong one is switched off.
	CPoseGraph g;
	for (int i = 0; i < 10; ++i) g.addNode(i, {double(i), 0, 0});
	for (size_t i = 1; i < 10; ++i) g.addEdge(edge(i - 1, i, {1, 0, 0}, EEdgeKind::sequential, 400.0));
	const size_t good = g.addEdge(edge(0, 9, {9, 0, 0}, EEdgeKind::loop, 100.0));
	const size_t bad = g.addEdge(edge(2, 8, {3, 0.5, 0}, EEdgeKind::loop, 100.0));
	const auto r = g.optimize();
	ASSERT_EQ(r.dropped_edges.size(), 1u);
	EXPECT_EQ(r.dropped_edges[0], bad);
	EXPECT_FALSE(g.edges()[bad].active);
	EXPECT_TRUE(g.edges()[good].active);
	for (int i = 0; i < 10; ++i) EXPECT_NEAR(g.nodes()[i].pose.x, i, 1e-3);
}

TEST(PoseGraph, ExportIsReadByMrptGraphClasses)
{
	CPoseGraph g;
	g.addNode(0, {0, 0, 0});
	g.addNode(1, {1, 0.5, 0.2});
	g.addEdge(edge(0, 1, {1, 0.5, 0.2}, EEdgeKind::sequential, 25.0));
	std::stringstream text;
	g.writeGraphText(text);
	EXPECT_NE(text.str().find("VERTEX_SE2"), std::string::npos);
	EXPECT_NE(text.str().find("EDGE_SE2"), std::string::npos);
	mrpt::graphs::CNetworkOfPoses2DInf back;
	back.readAsText(text);
	ASSERT_EQ(back.nodes.size(), 2u);
	ASSERT_EQ(back.edges.size(), 1u);
	EXPECT_NEAR(back.nodes.at(1).x(), 1.0, 1e-6);
	EXPECT_NEAR(back.edges.begin()->second.cov_inv(0, 0), 25.0, 1e-6);
}

TEST(PoseGraph, BadEdgesAreRejectedWithAClearError)
{
	CPoseGraph g;
	g.addNode(0, {0, 0, 0});
	EXPECT_THROW(g.addEdge(edge(0, 5, {1, 0, 0}, EEdgeKind::sequential)), std::invalid_argument);
	g.addNode(1, {1, 0, 0});
	auto e = edge(0, 1, {1, 0, 0}, EEdgeKind::sequential);
	e.information(2, 2) = -1;
	EXPECT_THROW(g.addEdge(e), std::invalid_argument);
}

namespace
{
/** Two laps of a 30-keyframe circle (radius 3 m) with noisy, biased
 * sequential edges and a loop edge every 5 keyframes of the second lap; the
 * nodes start at the dead-reckoned chain. */
CPoseGraph noisyLaps(const std::string& solver)
{
	TPoseGraphOptions o;
	o.solver = solver;
	CPoseGraph g(o);
	const auto truth = [](int k) {
		const double a = k * 2 * M_PI / 30;
		return TPose2D(3 * std::sin(a), 3 * (1 - std::cos(a)), mrpt::math::wrapToPi(a));
	};
	const auto noise = [](int k, int salt) { return 0.01 * std::sin(12.9898 * k + 78.233 * salt); };  // deterministic
	g.addNode(0, truth(0));
	for (int k = 1; k < 60; ++k)
	{
		auto rel = relativePose(truth(k - 1), truth(k));
		rel.x += noise(k, 1), rel.y += noise(k, 2), rel.phi += 0.02 + noise(k, 3);
		g.addNode(k, composePose(g.nodes()[k - 1].pose, rel));
		g.addEdge(edge(k - 1, k, rel, EEdgeKind::sequential, 100.0));
		if (k >= 30 && k % 5 == 0) g.addEdge(edge(k - 30, k, relativePose(truth(k - 30), truth(k)), EEdgeKind::loop, 400.0));
	}
	return g;
}
}  // namespace

TEST(PoseGraph, SparseSolverReachesMrptsOptimum)
{
	// Same model, two solvers: Eigen's sparse Cholesky (default) and MRPT's
	// optimize_graph_spa_levmarq. The chain starts 1.2 rad of heading off
	// after two laps (0.02 rad bias per edge); both must reach the same chi2
	// and the same poses.
	auto sparse = noisyLaps("sparse"), mrpt = noisyLaps("mrpt");
	const auto rs = sparse.optimize(), rm = mrpt.optimize();
	EXPECT_GT(rs.initial_chi2, 1000.0);
	EXPECT_NEAR(rs.final_chi2, rm.final_chi2, 1e-4 * rm.final_chi2);
	EXPECT_LT(rs.final_chi2, 0.01 * rs.initial_chi2);
	double maxDiff = 0;
	for (size_t k = 0; k < sparse.nodeCount(); ++k)
	{
		const auto &a = sparse.nodes()[k].pose, &b = mrpt.nodes()[k].pose;
		maxDiff = std::max({maxDiff, std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(mrpt::math::wrapToPi(a.phi - b.phi))});
	}
	EXPECT_LT(maxDiff, 1e-4);
	std::cout << "chi2 " << rs.initial_chi2 << " -> sparse " << rs.final_chi2 << " (" << rs.iterations
			  << " it), MRPT " << rm.final_chi2 << " (" << rm.iterations << " it); max pose difference " << maxDiff
			  << "\n";
}
