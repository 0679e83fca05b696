/* The branch-and-bound search of CCorrelativeScanMatcher (libs/graph
 * branch_and_bound.h) against an exhaustive search over every rotation and
 * offset of the window: with rotation groups at the top it must still find
 * the best leaf exactly. */
#include <gtest/gtest.h>
#include <hslam/graph/CMultiResolutionGrid.h>

#include <cmath>

#include "../../libs/graph/src/branch_and_bound.h"
#include "sim_scans.h"

using namespace hslam::graph;
using namespace hslam::graph::testing;
using mrpt::math::TPose2D;

namespace
{
/** The query rotated over +-halfCount steps about `guess`, each step moving
 * the farthest point by one cell at most, as CCorrelativeScanMatcher does. */
std::vector<detail::TRotatedQuery> rotatedQueries(const CMultiResolutionGrid& grid, const TPointCloud2D& query,
												  const TPose2D& guess, int halfCount)
{
	double r2 = 0;
	for (const auto& p : query) r2 = std::max(r2, static_cast<double>(p.x) * p.x + static_cast<double>(p.y) * p.y);
	const double res = grid.resolution_m(), step = std::acos(1.0 - res * res / (2.0 * r2));
	std::vector<detail::TRotatedQuery> out(static_cast<size_t>(2 * halfCount + 1));
	for (int j = -halfCount; j <= halfCount; ++j)
	{
		auto& q = out[static_cast<size_t>(j + halfCount)];
		q.yaw_rad = guess.phi + j * step;
		const double c = std::cos(q.yaw_rad), s = std::sin(q.yaw_rad);
		for (const auto& p : query)
		{
			q.cx.push_back(grid.cellX(guess.x + c * p.x - s * p.y));
			q.cy.push_back(grid.cellY(guess.y + s * p.x + c * p.y));
		}
	}
	return out;
}

/** Mean finest-level value of rotation r shifted by (dx, dy). */
float leafScore(const CMultiResolutionGrid& grid, const detail::TRotatedQuery& q, int dx, int dy)
{
	unsigned sum = 0;
	for (size_t i = 0; i < q.cx.size(); ++i) sum += grid.value(0, q.cx[i] + dx, q.cy[i] + dy);
	return static_cast<float>(sum) / (255.f * static_cast<float>(q.cx.size()));
}

/** The irregular room's scan from `robot`, in the world frame (a reference). */
TPointCloud2D roomSeenFrom(const TPose2D& robot, std::mt19937_64& rng)
{
	return transformPoints(scanPoints(irregularRoom(), robot, rng), robot);
}

float exhaustiveBest(const CMultiResolutionGrid& grid, const std::vector<detail::TRotatedQuery>& rotations, int w,
					 const std::function<bool(int, int, int)>& excluded)
{
	float best = 0;
	for (int r = 0; r < static_cast<int>(rotations.size()); ++r)
		for (int dx = -w; dx <= w; ++dx)
			for (int dy = -w; dy <= w; ++dy)
				if (!excluded || !excluded(r, dx, dy))
					best = std::max(best, leafScore(grid, rotations[static_cast<size_t>(r)], dx, dy));
	return best;
}
}  // namespace

TEST(BranchAndBound, FindsTheExhaustiveBestOverRotationGroups)
{
	// A sparse reference (every 4th point) with a thin kernel keeps the pooled
	// levels far from saturated: a bound that misses a member rotation by a
	// cell shows as a wrong best.
	std::mt19937_64 rng(3);
	const auto world = irregularRoom();
	const auto all = roomSeenFrom({4.0, 3.5, 0.4}, rng);
	TPointCloud2D sparse;
	for (size_t i = 0; i < all.size(); i += 4) sparse.push_back(all[i]);
	std::uniform_real_distribution<double> u(-1.0, 1.0);
	const auto none = std::function<bool(int, int, int)>();
	int cases = 0;
	for (const int levels : {4, 5})  // top level 3 / 4: groups of 3 / 7 rotations
	{
		CMultiResolutionGrid grid;
		grid.build(sparse, 0.05, 0.02, levels);
		for (int trial = 0; trial < 12; ++trial)
		{
			const TPose2D from{4.0 + 0.5 * u(rng), 3.5 + 0.5 * u(rng), 0.4 + 0.3 * u(rng)};
			const auto query = scanPoints(world, from, rng);
			const int halfCount = 4 + 4 * trial, w = trial % 3 == 0 ? 2 : 6;
			const auto rotations = rotatedQueries(grid, query, {from.x + 0.05, from.y - 0.05, from.phi}, halfCount);
			const float truth = exhaustiveBest(grid, rotations, w, none);
			const auto found = detail::branchAndBound(grid, rotations, w, 0.f, none);
			ASSERT_TRUE(found.found);
			EXPECT_FLOAT_EQ(found.best.score, truth) << levels << " levels, trial " << trial;
			EXPECT_FLOAT_EQ(leafScore(grid, rotations[static_cast<size_t>(found.best.rotation)], found.best.dx,
									  found.best.dy),
							truth);
			EXPECT_FALSE(detail::branchAndBound(grid, rotations, w, truth, none).found);  // nothing above the best
			// the existence test: some leaf above a bound below the best, none above the best
			const auto any = detail::branchAndBound(grid, rotations, w, 0.9f * truth, none, true);
			ASSERT_TRUE(any.found);
			EXPECT_GT(any.best.score, 0.9f * truth);
			EXPECT_FLOAT_EQ(
				leafScore(grid, rotations[static_cast<size_t>(any.best.rotation)], any.best.dx, any.best.dy),
				any.best.score);
			EXPECT_FALSE(detail::branchAndBound(grid, rotations, w, truth, none, true).found);
			// leaving out the winner's neighbourhood: the exhaustive second best
			const auto winner = found.best;
			const std::function<bool(int, int, int)> near = [&](int r, int dx, int dy) {
				return std::abs(r - winner.rotation) <= 2 && std::abs(dx - winner.dx) <= 2 &&
					   std::abs(dy - winner.dy) <= 2;
			};
			const float second = exhaustiveBest(grid, rotations, w, near);
			if (second > 0)
			{
				EXPECT_FLOAT_EQ(detail::branchAndBound(grid, rotations, w, 0.f, near).best.score, second);
			}
			// an exclusion wide enough to hold whole nodes (pruned unscored):
			// still the exhaustive best outside it, and the existence test agrees
			const int half = w, rotHalf = halfCount;
			const std::function<bool(int, int, int)> wide = [&](int r, int dx, int dy) {
				return std::abs(r - winner.rotation) <= rotHalf && std::hypot(dx - winner.dx, dy - winner.dy) <= half;
			};
			const float outside = exhaustiveBest(grid, rotations, w, wide);
			const auto searched = detail::branchAndBound(grid, rotations, w, 0.f, wide);
			EXPECT_EQ(searched.found, outside > 0);
			if (outside > 0)
			{
				EXPECT_FLOAT_EQ(searched.best.score, outside);
				EXPECT_FALSE(wide(searched.best.rotation, searched.best.dx, searched.best.dy));
			}
			EXPECT_EQ(detail::branchAndBound(grid, rotations, w, 0.95f * outside, wide, true).found, outside > 0);
			++cases;
		}
	}
	EXPECT_EQ(cases, 24);
}

TEST(BranchAndBound, RotationsFilledOnDemandGiveTheSameSearchAndSkipUnexpandedOnes)
{
	// The matcher hands the search yaws only and fills a rotation's cells when
	// the search first reads them: same leaves, same nodes scored; a search
	// whose bound prunes whole rotation groups never fills their members.
	std::mt19937_64 rng(5);
	const TPose2D robot{4.0, 3.5, 0.4};
	CMultiResolutionGrid grid;
	grid.build(roomSeenFrom(robot, rng), 0.05, 0.05, 6);
	const auto query = scanPoints(irregularRoom(), {4.1, 3.45, 0.45}, rng);
	const auto filled = rotatedQueries(grid, query, robot, 40);
	std::vector<detail::TRotatedQuery> yawsOnly(filled.size());
	for (size_t k = 0; k < filled.size(); ++k) yawsOnly[k].yaw_rad = filled[k].yaw_rad;
	size_t fills = 0;
	const detail::TRotationFiller fill = [&](detail::TRotatedQuery& r) {
		++fills;
		for (const auto& f : filled)
			if (f.yaw_rad == r.yaw_rad) r.cx = f.cx, r.cy = f.cy;
	};
	const auto none = std::function<bool(int, int, int)>();
	for (const float bound : {0.3f, 0.6f})
		for (const bool firstAbove : {false, true})
		{
			fills = 0;
			const auto eager = detail::branchAndBound(grid, filled, 6, bound, none, firstAbove);
			const auto lazy = detail::branchAndBound(grid, yawsOnly, fill, 6, bound, none, firstAbove);
			ASSERT_EQ(lazy.found, eager.found);
			EXPECT_EQ(lazy.best.rotation, eager.best.rotation);
			EXPECT_EQ(lazy.best.dx, eager.best.dx);
			EXPECT_EQ(lazy.best.dy, eager.best.dy);
			EXPECT_FLOAT_EQ(lazy.best.score, eager.best.score);
			EXPECT_EQ(lazy.nodesScored, eager.nodesScored);
			EXPECT_LE(fills, filled.size());
			if (firstAbove)
			{
				EXPECT_LT(fills, filled.size()) << "bound " << bound;
			}
		}
}

TEST(BranchAndBound, SearchFromTheCentreScoreFindsTheSameLeafScoringFewerNodes)
{
	// The search for the best leaf starts from the window centre's score (the
	// guess): same leaf, ties included, as the search from minScore alone
	// (which a search with exclusions still is: an exclusion of nothing gives
	// it), with fewer nodes scored when the guess is near the truth.
	std::mt19937_64 rng(11);
	const TPose2D robot{4.0, 3.5, 0.4};
	CMultiResolutionGrid grid;
	grid.build(roomSeenFrom(robot, rng), 0.05, 0.05, 7);
	const std::function<bool(int, int, int)> nothing = [](int, int, int) { return false; };
	const auto none = std::function<bool(int, int, int)>();
	size_t fewer = 0, cases = 0;
	for (const double off_m : {0.0, 0.03, 0.1, 0.3})
	{
		const auto query = scanPoints(irregularRoom(), robot, rng);
		const auto rotations = rotatedQueries(grid, query, {robot.x + off_m, robot.y - off_m, robot.phi + off_m}, 30);
		for (const float minScore : {0.1f, 0.5f})
		{
			const auto fromCentre = detail::branchAndBound(grid, rotations, 10, minScore, none);
			const auto fromMin = detail::branchAndBound(grid, rotations, 10, minScore, nothing);
			ASSERT_EQ(fromCentre.found, fromMin.found) << off_m;
			EXPECT_EQ(fromCentre.best.rotation, fromMin.best.rotation) << off_m;
			EXPECT_EQ(fromCentre.best.dx, fromMin.best.dx) << off_m;
			EXPECT_EQ(fromCentre.best.dy, fromMin.best.dy) << off_m;
			EXPECT_FLOAT_EQ(fromCentre.best.score, fromMin.best.score) << off_m;
			EXPECT_LE(fromCentre.nodesScored, fromMin.nodesScored + 1) << off_m;  // + the centre itself
			fewer += fromCentre.nodesScored < fromMin.nodesScored ? 1 : 0;
			++cases;
		}
	}
	EXPECT_EQ(cases, 8u);
	EXPECT_GE(fewer, 4u);  // at least where the guess is within a few cells
}
