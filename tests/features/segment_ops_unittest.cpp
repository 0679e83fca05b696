/* Shared extractor steps: thesis eq. 56 gap criterion, IEP split, merging,
 * derivative segmentation, scoring. */
#include "line_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/features/CDerivativeLineExtractor.h>
#include <hslam/benchdata/line_scoring.h>
#include <hslam/features/segment_ops.h>

using namespace hslam::features;
using namespace hslam::benchdata;

namespace
{
/** Points (x, y) with consecutive beam indices. */
TScanPoints makePoints(const std::vector<mrpt::math::TPoint2D>& xy)
{
	TScanPoints p;
	for (size_t i = 0; i < xy.size(); ++i)
	{
		p.xy.push_back(xy[i]);
		p.range_m.push_back(std::hypot(xy[i].x, xy[i].y));
		p.beam.push_back(i);
	}
	return p;
}

std::vector<mrpt::math::TPoint2D> row(double x0, double dx, int n, double y)
{
	std::vector<mrpt::math::TPoint2D> v;
	for (int i = 0; i < n; ++i) v.emplace_back(x0 + i * dx, y);
	return v;
}
}  // namespace

TEST(GapCriterion, ThesisEquation56)
{
	// one wall sampled every 0.1 m, cut in two halves of 10 points: no gap beyond
	// the spacing -> (0 + a + b) / (a + b) = 1
	auto pts = makePoints(row(0, 0.1, 20, 1));
	EXPECT_NEAR(gapCriterion(pts, {0, 10}, {10, 20}), 1.0, 1e-12);
	// halves 0.9 m long with 1.0 m between facing points: aa = 1.0 - 0.1 = 0.9,
	// (0.9 + 1.8) / 1.8 = 1.5 > 1.05: a real gap
	auto a = row(0, 0.1, 10, 1), b = row(1.9, 0.1, 10, 1);
	a.insert(a.end(), b.begin(), b.end());
	pts = makePoints(a);
	EXPECT_NEAR(gapCriterion(pts, {0, 10}, {10, 20}), 1.5, 1e-12);
	// a single point has no extent
	EXPECT_TRUE(std::isinf(gapCriterion(makePoints(row(0, 0.1, 2, 1)), {0, 1}, {1, 2})));
}

TEST(SplitByChord, SplitsAtTheCornerOnly)
{
	// an L: 10 points along y = 0 then 10 points up x = 0.9
	auto v = row(0, 0.1, 10, 0);
	for (int i = 1; i <= 10; ++i) v.emplace_back(0.9, 0.1 * i);
	const auto pts = makePoints(v);
	const auto parts = splitByChord(pts, {0, 20}, 0.05);
	ASSERT_EQ(parts.size(), 2u);
	EXPECT_EQ(parts[0].begin, 0u);
	EXPECT_EQ(parts[0].end, 9u);  // the corner point (index 9) starts the second part
	EXPECT_EQ(parts[1].end, 20u);
	// a straight row is never split
	EXPECT_EQ(splitByChord(makePoints(row(0, 0.1, 30, 2)), {0, 30}, 0.01).size(), 1u);
}

TEST(SplitAtPointGaps, CutsOnlyLargeSteps)
{
	auto a = row(0, 0.1, 5, 1), b = row(1.5, 0.1, 5, 1);
	a.insert(a.end(), b.begin(), b.end());
	const auto parts = splitAtPointGaps(makePoints(a), {0, 10}, 0.5);
	ASSERT_EQ(parts.size(), 2u);
	EXPECT_EQ(parts[0].end, 5u);
	EXPECT_EQ(parts[1].begin, 5u);
}

TEST(MergeCollinearNeighbours, MergesOneWallButNotParallelOrAngledWalls)
{
	TMergeRule rule;
	rule.max_angle_rad = 10 * M_PI / 180;
	rule.max_rms_growth = 2;
	rule.max_gap_ratio = 1.05;
	// one wall cut in 3 pieces with 5 mm zigzag noise: merged back into one
	std::vector<mrpt::math::TPoint2D> v;
	for (int i = 0; i < 30; ++i) v.emplace_back(0.1 * i, 1 + ((i / 2) % 2 ? 0.005 : -0.005));
	auto pts = makePoints(v);
	std::vector<TIndexRange> ranges{{0, 10}, {10, 20}, {20, 30}};
	mergeCollinearNeighbours(pts, ranges, rule);
	ASSERT_EQ(ranges.size(), 1u);
	EXPECT_EQ(ranges[0].end, 30u);
	// two parallel walls 10 cm apart (a door recess): kept apart
	auto a = row(0, 0.1, 15, 1), b = row(1.5, 0.1, 15, 1.1);
	a.insert(a.end(), b.begin(), b.end());
	pts = makePoints(a);
	ranges = {{0, 15}, {15, 30}};
	mergeCollinearNeighbours(pts, ranges, rule);
	EXPECT_EQ(ranges.size(), 2u);
	// 20 deg corner
	v = row(0, 0.1, 15, 0);
	for (int i = 1; i <= 15; ++i) v.emplace_back(1.4 + 0.1 * i * std::cos(0.349), 0.1 * i * std::sin(0.349));
	pts = makePoints(v);
	ranges = {{0, 15}, {15, 30}};
	mergeCollinearNeighbours(pts, ranges, rule);
	EXPECT_EQ(ranges.size(), 2u);
}

TEST(DerivativeSegmentation, PeaksAtCornersAndJumpsOnly)
{
	// noiseless box room: pieces start at the run start and at the corner beams
	const auto sim = test::simulate(test::boxRoom(0));
	const CDerivativeLineExtractor ex;
	const TScanPoints pts = hslam::common::makeRangeData(sim.scan).points;
	const auto pieces = ex.segmentByDerivative(pts);
	ASSERT_EQ(pieces.size(), 3u);
	EXPECT_NEAR(static_cast<double>(pts.beam[pieces[1].begin]), test::kRightCornerBeam, 1.0);
	EXPECT_NEAR(static_cast<double>(pts.beam[pieces[2].begin]), test::kLeftCornerBeam, 1.0);
	// thesis step k = 1 finds the same corners
	CDerivativeLineExtractor::TOptions o;
	o.derivative_step_rad = M_PI / 180;  // k = 1
	const auto piecesK1 = CDerivativeLineExtractor(o).segmentByDerivative(pts);
	ASSERT_EQ(piecesK1.size(), 3u);
	EXPECT_NEAR(static_cast<double>(pts.beam[piecesK1[1].begin]), test::kRightCornerBeam, 1.0);
}

TEST(DerivativeSegmentation, OneLargeJumpDoesNotHideCorners)
{
	// a far wall at 8 m seen through a gap next to the room corner: the depth
	// jump 4 m -> 8 m (|d2| ~ 0.7) dwarfs the corner peaks (|d2| ~ 0.04)
	std::vector<TWall> walls = test::boxRoom(0);
	walls[2] = {{4, 2}, {2, 2}, 0};  // left wall only up to x = 2, then open
	walls.push_back({{8, 2.5}, {-1, 8}, 0});  // far wall behind the opening
	const auto sim = test::simulate(walls);
	const CDerivativeLineExtractor ex;
	const TScanPoints pts = hslam::common::makeRangeData(sim.scan).points;
	bool rightCorner = false, leftCorner = false;
	for (const auto& p : ex.segmentByDerivative(pts))
	{
		rightCorner |= std::abs(static_cast<double>(pts.beam[p.begin]) - test::kRightCornerBeam) <= 1.0;
		leftCorner |= std::abs(static_cast<double>(pts.beam[p.begin]) - test::kLeftCornerBeam) <= 1.0;
	}
	EXPECT_TRUE(rightCorner);
	EXPECT_TRUE(leftCorner);
}

TEST(LineScoring, FoundFalsePositivesAndEndpointError)
{
	TVisibleWall t;
	t.p0 = {2, -1};
	t.p1 = {2, 1};
	TLineSegment s;
	s.p0 = {2.01, -0.98};
	s.p1 = {2.01, 1.02};
	s.rho_m = 2.01;
	s.alpha_rad = 0;
	TLineScore score = scoreLines({t}, {s});
	EXPECT_EQ(score.found, 1u);
	EXPECT_EQ(score.false_positives, 0u);
	EXPECT_NEAR(score.meanEndpointError_m(), std::hypot(0.01, 0.02), 1e-12);
	EXPECT_DOUBLE_EQ(score.f1(), 1.0);
	// the wall split 70/30: the long part matches, the short one is a false positive
	TLineSegment a = s, b = s;
	a.p1 = {2.01, 0.4};
	b.p0 = {2.01, 0.45};
	score = scoreLines({t}, {a, b});
	EXPECT_EQ(score.found, 1u);
	EXPECT_EQ(score.false_positives, 1u);
	EXPECT_NEAR(score.f1(), 2 * 0.5 * 1 / 1.5, 1e-12);
	// 4 deg off, or 6 cm off: not found
	TLineSegment tilted = s;
	tilted.alpha_rad = 4 * M_PI / 180;
	EXPECT_EQ(scoreLines({t}, {tilted}).found, 0u);
	TLineSegment shifted = s;
	shifted.p0.x = shifted.p1.x = 2.06;
	EXPECT_EQ(scoreLines({t}, {shifted}).found, 0u);
}

TEST(SyntheticScan, ExactRangesAndNoEchoBeams)
{
	const auto sim = test::simulate({{{4, -1}, {4, 1}, 0}});
	EXPECT_NEAR(sim.scan.getScanRange(90), 4.0, 1e-6);  // straight ahead
	EXPECT_TRUE(sim.scan.getScanRangeValidity(90));
	EXPECT_NEAR(sim.scan.getScanRange(100), 4.0 / std::cos(10 * M_PI / 180), 1e-5);
	EXPECT_FALSE(sim.scan.getScanRangeValidity(0));  // nothing at -90 deg
	EXPECT_EQ(sim.wall_of_beam[0], -1);
	const auto vis = visibleWalls(sim, 5, 0.2);
	ASSERT_EQ(vis.size(), 1u);
	EXPECT_EQ(vis[0].first_beam, 90u - 14u);  // atan(1/4) = 14.04 deg
	EXPECT_EQ(vis[0].last_beam, 90u + 14u);
}
