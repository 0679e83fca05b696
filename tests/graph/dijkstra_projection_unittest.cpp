/* dijkstraProjection / swapFixedEnd: relative covariances through a pose
 * graph, against hand-derived chains and against each other. */
#include <gtest/gtest.h>
#include <hslam/graph/dijkstra_projection.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Dense>

using namespace hslam::graph;
using mrpt::math::TPose2D;

namespace
{
constexpr double kXyVar = 0.01, kYawVar = 0.0004;  // a = 0.1 m^2 sigma, b = 0.02 rad sigma

TGraphEdge edge(const CPoseGraph& g, size_t a, size_t b, const Eigen::Matrix3d& cov, EEdgeKind kind)
{
	TGraphEdge e;
	e.from = a, e.to = b, e.kind = kind;
	e.relative = (mrpt::poses::CPose2D(g.nodes()[b].pose) - mrpt::poses::CPose2D(g.nodes()[a].pose)).asTPose();
	e.information = cov.inverse();
	return e;
}

Eigen::Matrix3d stepCov() { return Eigen::Vector3d(kXyVar, kXyVar, kYawVar).asDiagonal(); }

/** Nodes at x = 0, 1, 2 (yaw 0), sequential edges of covariance diag(a, a, b). */
CPoseGraph straightChain()
{
	CPoseGraph g;
	for (int i = 0; i < 3; ++i) g.addNode(i, {double(i), 0, 0});
	g.addEdge(edge(g, 0, 1, stepCov(), EEdgeKind::sequential));
	g.addEdge(edge(g, 1, 2, stepCov(), EEdgeKind::sequential));
	return g;
}
}  // namespace

TEST(DijkstraProjection, StraightChainMatchesTheHandPropagation)
{
	// node 2 = node 0 (+) r1 (+) r2, noise in each from-frame:
	// y2 = n1y + 1 m * n1yaw + n2y -> var 2a + b; cov(y2, yaw2) = b; var yaw2 = 2b.
	const auto cov = dijkstraProjection(straightChain(), 0);
	ASSERT_TRUE(cov[0] && cov[1] && cov[2]);
	EXPECT_NEAR(cov[0]->norm(), 0.0, 1e-15);
	EXPECT_NEAR(((*cov[1]) - stepCov()).norm(), 0.0, 1e-12);
	Eigen::Matrix3d expected;
	expected << 2 * kXyVar, 0, 0, 0, 2 * kXyVar + kYawVar, kYawVar, 0, kYawVar, 2 * kYawVar;
	EXPECT_NEAR(((*cov[2]) - expected).norm(), 0.0, 1e-12);
}

TEST(DijkstraProjection, BackwardsAlongTheChainTheLeverOfEachStepCounts)
{
	// node 0 with node 2 fixed: yaw0 = -n1yaw - n2yaw and
	// y0 = n1yaw + 2 n2yaw - n1y - n2y -> var 2a + 5b, cov(y0, yaw0) = -3b.
	const auto cov = dijkstraProjection(straightChain(), 2);
	ASSERT_TRUE(cov[0]);
	Eigen::Matrix3d expected;
	expected << 2 * kXyVar, 0, 0, 0, 2 * kXyVar + 5 * kYawVar, -3 * kYawVar, 0, -3 * kYawVar, 2 * kYawVar;
	EXPECT_NEAR(((*cov[0]) - expected).norm(), 0.0, 1e-12);
}

TEST(DijkstraProjection, ALoopEdgeIsTheTighterPathAndAnInactiveOneIsNot)
{
	auto g = straightChain();
	const Eigen::Matrix3d tight = Eigen::Vector3d(1e-4, 1e-4, 1e-6).asDiagonal();
	const size_t loop = g.addEdge(edge(g, 0, 2, tight, EEdgeKind::loop));
	auto cov = dijkstraProjection(g, 0);
	EXPECT_NEAR(((*cov[2]) - tight).norm(), 0.0, 1e-12);
	// node 1 keeps its own edge (trace 2a + b): through node 2 it would add a
	// backward step of trace 2a + 2b on top of the loop's
	EXPECT_NEAR(((*cov[1]) - stepCov()).norm(), 0.0, 1e-12);
	g.setEdgeActive(loop, false);
	cov = dijkstraProjection(g, 0);
	EXPECT_GT(cov[2]->trace(), 4 * kXyVar);
}

TEST(DijkstraProjection, UnconnectedNodesHaveNoValue)
{
	auto g = straightChain();
	g.addNode(3, {5, 5, 0});
	const auto cov = dijkstraProjection(g, 0);
	ASSERT_EQ(cov.size(), 4u);
	EXPECT_TRUE(cov[2].has_value());
	EXPECT_FALSE(cov[3].has_value());
	const auto none = dijkstraProjection(g, 7);  // no such source
	ASSERT_EQ(none.size(), 4u);
	for (const auto& c : none) EXPECT_FALSE(c.has_value());
}

TEST(DijkstraProjection, SwappingTheFixedEndEqualsProjectingFromTheOtherEnd)
{
	// A turning chain (yaw changes, both edge directions): on a tree the
	// projection is exact to first order, so fixing the other end must give
	// the same matrix either way.
	CPoseGraph g;
	mrpt::poses::CPose2D p(1.0, -2.0, 0.3);
	g.addNode(0, p.asTPose());
	const TPose2D steps[] = {{1.0, 0.2, 0.4}, {0.8, -0.1, -0.2}, {1.2, 0.3, 0.9}, {0.5, 0.0, -0.5}};
	Eigen::Matrix3d c = stepCov();
	c(0, 1) = c(1, 0) = 0.3 * kXyVar;
	for (size_t i = 0; i < 4; ++i)
	{
		p = p + mrpt::poses::CPose2D(steps[i]);
		g.addNode(static_cast<int64_t>(i + 1), p.asTPose());
		// odd edges stored backwards: traversed against their direction
		if (i % 2) g.addEdge(edge(g, i + 1, i, c, EEdgeKind::sequential));
		else g.addEdge(edge(g, i, i + 1, c, EEdgeKind::sequential));
	}
	const auto from0 = dijkstraProjection(g, 0);
	const auto from4 = dijkstraProjection(g, 4);
	const Eigen::Matrix3d swapped = swapFixedEnd(g.nodes()[0].pose, g.nodes()[4].pose, *from0[4]);
	EXPECT_NEAR((swapped - *from4[0]).norm() / from4[0]->norm(), 0.0, 1e-9);
	// and swapping twice is the identity
	const Eigen::Matrix3d back = swapFixedEnd(g.nodes()[4].pose, g.nodes()[0].pose, swapped);
	EXPECT_NEAR((back - *from0[4]).norm() / from0[4]->norm(), 0.0, 1e-9);
}
