/* The free-side check and the confirmation of loop closures on hand-built
 * cases: a wall seen from behind, and two closures that ask for the same or
 * for different corrections. */
#include <hslam/graph/CLoopClosureDetector.h>
#include <hslam/graph/free_space_check.h>

#include <gtest/gtest.h>

using namespace hslam::graph;
using mrpt::math::TPoint2Df;
using mrpt::math::TPose2D;

namespace
{
/** Points every 2 cm on the segment y = y_m, x in [x0, x1]. */
std::vector<TPoint2Df> wallPoints(double y_m, double x0, double x1)
{
	std::vector<TPoint2Df> out;
	for (double x = x0; x <= x1; x += 0.02) out.push_back({static_cast<float>(x), static_cast<float>(y_m)});
	return out;
}

/** The points of `world` seen from `origin`, in the frame of a robot at origin with yaw 0. */
std::vector<TPoint2Df> fromRobotAt(const std::vector<TPoint2Df>& world, TPoint2Df origin)
{
	std::vector<TPoint2Df> out;
	for (const auto& p : world) out.push_back({p.x - origin.x, p.y - origin.y});
	return out;
}

/** A submap of a corridor along x (walls y = -0.75 and y = 0.75, x in
 * [-5, 5]) seen from three places on its axis. */
struct TCorridorSubmap
{
	CMultiResolutionGrid grid;
	CObservedFreeSpace free;
	TCorridorSubmap()
	{
		auto walls = wallPoints(-0.75, -5, 5);
		const auto upper = wallPoints(0.75, -5, 5);
		walls.insert(walls.end(), upper.begin(), upper.end());
		std::vector<TSubmapView> views;
		for (const float x : {-2.0f, 0.0f, 2.0f}) views.push_back({{x, 0.0f}, walls});
		grid.build(walls, 0.05, 0.05, 1);
		free.build(grid, views);
	}
};
}  // namespace

TEST(FreeSideCheck, WallSeenFromItsOwnSideCounts)
{
	const TCorridorSubmap s;
	// a robot on the corridor's axis sees the upper wall from below, as the submap did
	const auto f = freeSideFigures(s.grid, s.free, fromRobotAt(wallPoints(0.75, -3, 3), {0, 0}), TPose2D(0, 0, 0));
	EXPECT_GT(f.wall_hits, 250u);  // 301 points on the wall
	EXPECT_GT(f.fraction(), 0.98);
}

TEST(FreeSideCheck, WallSeenFromBehindIsFlagged)
{
	const TCorridorSubmap s;
	// a robot in a parallel corridor above (y = 1.5) sees the same wall from above:
	// its end points fit the submap's wall exactly, but from the side the submap never saw
	const auto f = freeSideFigures(s.grid, s.free, fromRobotAt(wallPoints(0.75, -3, 3), {0, 1.5f}), TPose2D(0, 1.5, 0));
	EXPECT_GT(f.wall_hits, 250u);
	EXPECT_LT(f.fraction(), 0.02);
}

TEST(FreeSideCheck, NoWallHitsIsNoEvidence)
{
	const TCorridorSubmap s;
	const auto f = freeSideFigures(s.grid, s.free, {{0.3f, 0.0f}}, TPose2D(0, 0, 0));
	EXPECT_EQ(f.wall_hits, 0u);
	EXPECT_EQ(f.fraction(), 1.0);
}

TEST(ClosureConfirmation, ClosuresAskingForTheSameCorrectionAgree)
{
	// anchor at the origin; two query nodes 0.5 m apart whose estimates are both
	// 1 m short in x: two closures that both say "1 m further" agree, one that
	// says "1.5 m further" (0.5 m along the axis) does not, and neither does one
	// 5 deg off
	CPoseGraph graph;
	const size_t anchor = graph.addNode(0, TPose2D(0, 0, 0));
	const size_t q1 = graph.addNode(1, TPose2D(4.0, 0, 0)), q2 = graph.addNode(2, TPose2D(4.5, 0, 0));
	TLoopClosure a, b;
	a.anchor_node = b.anchor_node = anchor;
	a.query_node = q1, a.relative = TPose2D(5.0, 0, 0);
	b.query_node = q2, b.relative = TPose2D(5.5, 0, 0);
	const double yaw = mrpt::DEG2RAD(3.0);
	EXPECT_TRUE(closuresAgree(a, b, graph, 0.3, yaw));
	EXPECT_TRUE(closuresAgree(b, a, graph, 0.3, yaw));
	b.relative = TPose2D(6.0, 0, 0);
	EXPECT_FALSE(closuresAgree(a, b, graph, 0.3, yaw));
	EXPECT_TRUE(closuresAgree(a, b, graph, 0.6, yaw));  // 0.5 m apart
	b.relative = TPose2D(5.5, 0, mrpt::DEG2RAD(5.0));
	EXPECT_FALSE(closuresAgree(a, b, graph, 0.3, yaw));
}
