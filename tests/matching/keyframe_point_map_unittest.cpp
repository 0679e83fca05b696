/* CKeyframePointMap: keyframe decisions, point thinning, world transform and
 * the window of keyframes, with hand-computed points. */
#include <gtest/gtest.h>
#include <hslam/matching/CKeyframePointMap.h>

#include <cmath>

using namespace hslam::matching;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

std::vector<mrpt::math::TPoint2D> pointsOf(const mrpt::maps::CSimplePointsMap& map)
{
	std::vector<mrpt::math::TPoint2D> out;
	for (size_t i = 0; i < map.size(); ++i) out.push_back({map.getPointsBufferRef_x()[i], map.getPointsBufferRef_y()[i]});
	return out;
}
}  // namespace

TEST(KeyframePointMap, NewKeyframeAfterHalfAMetreOrFifteenDegrees)
{
	CKeyframePointMap map;  // defaults: 0.5 m, 15 deg
	EXPECT_TRUE(map.wantsKeyframe(CPose2D(3, 4, 1)));  // the first scan always
	map.addKeyframe(CPose2D(0, 0, 0), {{1, 0}});
	EXPECT_FALSE(map.wantsKeyframe(CPose2D(0.3, 0.3, 0)));  // 0.42 m
	EXPECT_TRUE(map.wantsKeyframe(CPose2D(0.3, 0.41, 0)));  // 0.508 m
	EXPECT_FALSE(map.wantsKeyframe(CPose2D(0, 0, 14 * kDeg)));
	EXPECT_TRUE(map.wantsKeyframe(CPose2D(0, 0, -16 * kDeg)));
	EXPECT_FALSE(map.wantsKeyframe(CPose2D(0, 0, 359 * kDeg)));  // -1 deg once wrapped
}

TEST(KeyframePointMap, PointsGoToTheWorldFrameThinnedByTheirSpacing)
{
	CKeyframePointMap map;  // min spacing 3 cm
	// Robot at (1, 2) facing +y: robot-frame (1, 0) is world (1, 3).
	map.addKeyframe(CPose2D(1, 2, 90 * kDeg), {{1, 0}, {1.02, 0}, {1.1, 0}});
	const auto points = pointsOf(map.reference(CPose2D(1, 2, 0)));
	ASSERT_EQ(points.size(), 2u);  // (1.02, 0) is 2 cm from (1, 0): skipped
	EXPECT_NEAR(points[0].x, 1.0, 1e-6);
	EXPECT_NEAR(points[0].y, 3.0, 1e-6);
	EXPECT_NEAR(points[1].x, 1.0, 1e-6);
	EXPECT_NEAR(points[1].y, 3.1, 1e-6);
}

TEST(KeyframePointMap, KeepsTheNewestKeyframesOnly)
{
	CKeyframePointMap::TOptions o;
	o.max_keyframes = 2;
	CKeyframePointMap map(o);
	for (int k = 0; k < 3; ++k) map.addKeyframe(CPose2D(k, 0, 0), {{0, 0}});
	EXPECT_EQ(map.keyframeCount(), 2u);
	const auto points = pointsOf(map.reference(CPose2D()));
	ASSERT_EQ(points.size(), 2u);
	EXPECT_NEAR(points[0].x, 1.0, 1e-6);  // keyframe 0 (x = 0) was dropped
	EXPECT_NEAR(points[1].x, 2.0, 1e-6);
}

TEST(KeyframePointMap, RadiusWindowFollowsTheRobot)
{
	CKeyframePointMap::TOptions o;
	o.radius_m = 5;
	CKeyframePointMap map(o);
	map.addKeyframe(CPose2D(0, 0, 0), {{0, 1}});
	map.addKeyframe(CPose2D(10, 0, 0), {{0, 1}});
	auto points = pointsOf(map.reference(CPose2D(9, 0, 0)));
	ASSERT_EQ(points.size(), 1u);
	EXPECT_NEAR(points[0].x, 10.0, 1e-6);
	points = pointsOf(map.reference(CPose2D(5, 0, 0)));  // both exactly 5 m away
	EXPECT_EQ(points.size(), 2u);
	points = pointsOf(map.reference(CPose2D(1, 0, 0)));
	ASSERT_EQ(points.size(), 1u);
	EXPECT_NEAR(points[0].x, 0.0, 1e-6);
}
