/* Line prediction and pairing (thesis 4.4.2 iii, figures 89-90) on walls
 * whose normal form after a known motion is worked out by hand. */
#include <gtest/gtest.h>
#include <hslam/matching/line_pairing.h>

#include <cmath>

using namespace hslam;
using features::TLineSegment;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

TLineSegment segment(mrpt::math::TPoint2D p0, mrpt::math::TPoint2D p1, double rho_m, double alpha_rad)
{
	TLineSegment s;
	s.p0 = p0;
	s.p1 = p1;
	s.rho_m = rho_m;
	s.alpha_rad = alpha_rad;
	return s;
}

/** The wall x = 2 (normal along +x), 2 m long. */
TLineSegment wallAhead() { return segment({2, -1}, {2, 1}, 2.0, 0.0); }
/** The wall y = 3 (normal along +y), 2 m long. */
TLineSegment wallLeft() { return segment({-1, 3}, {1, 3}, 3.0, M_PI / 2); }
}  // namespace

TEST(LinePairing, PredictionAfterATranslation)
{
	// 0.5 m forward: the wall ahead is 0.5 m closer, same normal.
	const auto p = matching::predictLineInCurrentFrame(wallAhead(), CPose2D(0.5, 0, 0));
	EXPECT_NEAR(p.rho_m, 1.5, 1e-12);
	EXPECT_NEAR(p.alpha_rad, 0.0, 1e-12);
	EXPECT_NEAR(p.p0.x, 1.5, 1e-12);
	EXPECT_NEAR(p.p0.y, -1.0, 1e-12);
}

TEST(LinePairing, PredictionAfterARotation)
{
	// Turning +90 deg in place: the wall ahead is now on the right, normal -90 deg,
	// still 2 m away; p0 (2, -1) becomes (-1, -2).
	const auto p = matching::predictLineInCurrentFrame(wallAhead(), CPose2D(0, 0, 90 * kDeg));
	EXPECT_NEAR(p.rho_m, 2.0, 1e-12);
	EXPECT_NEAR(p.alpha_rad, -90 * kDeg, 1e-12);
	EXPECT_NEAR(p.p0.x, -1.0, 1e-12);
	EXPECT_NEAR(p.p0.y, -2.0, 1e-12);
}

TEST(LinePairing, CrossingTheLineFlipsItsNormal)
{
	// Driving through x = 2 to x = 3: the line is 1 m behind, normal 180 deg.
	const auto p = matching::predictLineInCurrentFrame(wallAhead(), CPose2D(3, 0, 0));
	EXPECT_NEAR(p.rho_m, 1.0, 1e-12);
	EXPECT_NEAR(std::abs(p.alpha_rad), M_PI, 1e-12);
}

TEST(LinePairing, PairsEachWallWithItsMovedSelf)
{
	const features::TLineSegmentList previous{wallAhead(), wallLeft()};
	// After 0.5 m forward, current lines listed in the other order.
	const features::TLineSegmentList current{segment({-1.5, 3}, {0.5, 3}, 3.0, M_PI / 2),
											 segment({1.5, -1}, {1.5, 1}, 1.5, 0.0)};
	const auto pairs = matching::pairLines(previous, current, CPose2D(0.5, 0, 0), matching::TLinePairingOptions());
	ASSERT_EQ(pairs.size(), 2u);
	for (const auto& pair : pairs)
	{
		EXPECT_EQ(pair.current, 1 - pair.previous);
		EXPECT_NEAR(pair.cost, 0.0, 1e-12);  // exact prediction, equal lengths
	}
}

TEST(LinePairing, GatesRejectWrongDistanceAngleLengthAndShortLines)
{
	const matching::TLinePairingOptions o;  // gates: 0.5 m, 20 deg, 30 % length, 0.3 m
	const features::TLineSegmentList previous{wallAhead()};
	auto pairsWith = [&](const TLineSegment& s) { return matching::pairLines(previous, {s}, CPose2D(), o).size(); };
	EXPECT_EQ(pairsWith(segment({2.4, -1}, {2.4, 1}, 2.4, 0.0)), 1u);  // 0.4 m off: inside
	EXPECT_EQ(pairsWith(segment({2.6, -1}, {2.6, 1}, 2.6, 0.0)), 0u);  // 0.6 m off
	EXPECT_EQ(pairsWith(segment({2, -1}, {2, 1}, 2.0, 25 * kDeg)), 0u);  // normal 25 deg off
	EXPECT_EQ(pairsWith(segment({2, -0.6}, {2, 0.6}, 2.0, 0.0)), 0u);  // 1.2 m vs 2 m: 40 % shorter
	EXPECT_EQ(pairsWith(segment({2, -0.1}, {2, 0.1}, 2.0, 0.0)), 0u);  // 0.2 m: too short to pair
	EXPECT_EQ(pairsWith(segment({2, 4}, {2, 6}, 2.0, 0.0)), 0u);  // collinear but no overlap
}

TEST(LinePairing, EachLineIsUsedOnceLowestCostFirst)
{
	const features::TLineSegmentList previous{wallAhead()};
	const features::TLineSegmentList current{segment({2.3, -1}, {2.3, 1}, 2.3, 0.0), segment({2.1, -1}, {2.1, 1}, 2.1, 0.0)};
	const auto pairs = matching::pairLines(previous, current, CPose2D(), matching::TLinePairingOptions());
	ASSERT_EQ(pairs.size(), 1u);
	EXPECT_EQ(pairs[0].current, 1u);
	EXPECT_NEAR(pairs[0].cost, std::pow(0.1 / 0.5, 2), 1e-9);  // only the distance term
}
