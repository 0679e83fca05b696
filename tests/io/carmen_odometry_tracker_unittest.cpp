/* hslam tests: odometry re-anchoring and increments (CCarmenOdometryTracker). */
#include <gtest/gtest.h>
#include <hslam/io/CCarmenOdometryTracker.h>

#include "carmen_test_utils.h"

using hslam::io::CCarmenOdometryTracker;
using hslam::testing::carmen::expectPose;
using hslam::testing::carmen::handIncrement;
using mrpt::math::TPose2D;

TEST(CarmenOdometryTracker, AnchoredIncrementsInFileOrder)
{
	CCarmenOdometryTracker t;
	t.addOdometry({0.1, 0.0, 0.0}, 0, 0);  // raw, before the first scan -> chain_0
	const TPose2D ref0{1.0, 2.0, 0.5}, ref1{1.5, 2.2, 0.65};
	const auto s0 = t.addFrontScan({ref0});
	EXPECT_TRUE(s0.first);
	expectPose(s0.chainPose, {0.1, 0.0, 0.0});
	EXPECT_TRUE(t.addOdometry(ref0, 0, 0));  // anchor
	EXPECT_FALSE(t.addOdometry({1.2, 2.1, 0.6}, 0.3, 0.1));
	EXPECT_FALSE(t.addOdometry({1.4, 2.3, 0.7}, 0.4, 0.2));
	const auto s1 = t.addFrontScan({ref1});
	ASSERT_TRUE(s1.incrementKnown);
	expectPose(s1.increment, handIncrement(ref0, {1.4, 2.3, 0.7}));
	EXPECT_DOUBLE_EQ(s1.tv_mps, 0.4);
	EXPECT_DOUBLE_EQ(s1.rv_radps, 0.2);
	EXPECT_TRUE(t.addOdometry(ref1, 0, 0));
	EXPECT_FALSE(t.addOdometry({1.7, 2.0, 0.5}, 0, 0));
	const auto s2 = t.addFrontScan({{9, 9, 0}});
	ASSERT_TRUE(s2.incrementKnown);
	expectPose(s2.increment, handIncrement(ref1, {1.7, 2.0, 0.5}));
	expectPose(s2.chainPose, (mrpt::poses::CPose2D(0.1, 0, 0) + s1.increment + s2.increment).asTPose());
	EXPECT_EQ(t.anchors(), 2u);
}

TEST(CarmenOdometryTracker, MissingOdometryIsAGapNotZeroMotion)
{
	CCarmenOdometryTracker t;
	const TPose2D ref0{1, 1, 0};
	t.addFrontScan({ref0});
	t.addOdometry(ref0, 0, 0);  // anchor only, no raw odometry afterwards
	const auto s1 = t.addFrontScan({{2, 1, 0}});
	EXPECT_FALSE(s1.incrementKnown);
	expectPose(s1.chainPose, {0, 0, 0});  // chain does not move over a gap
	t.addOdometry({2, 1, 0}, 0, 0);  // anchor
	t.addOdometry({2.5, 1, 0}, 0, 0);
	const auto s2 = t.addFrontScan({{3, 1, 0}});
	ASSERT_TRUE(s2.incrementKnown);
	expectPose(s2.increment, {0.5, 0, 0});
}

TEST(CarmenOdometryTracker, UncorrectedLogWithoutAnchors)
{
	CCarmenOdometryTracker t;
	const auto s0 = t.addFrontScan({{5, 5, 1}});  // no odometry before the first scan
	expectPose(s0.chainPose, {0, 0, 0});
	EXPECT_FALSE(t.addOdometry({0.2, 0, 0}, 0, 0));  // differs from the scan pose: raw
	const auto s1 = t.addFrontScan({{5, 5, 1}});
	EXPECT_FALSE(s1.incrementKnown);  // odometry at scan 0 was unknown
	t.addOdometry({0.5, 0.1, 0.1}, 0, 0);
	t.addOdometry({0.7, 0.1, 0.2}, 0, 0);
	const auto s2 = t.addFrontScan({{5, 5, 1}});
	ASSERT_TRUE(s2.incrementKnown);
	expectPose(s2.increment, handIncrement({0.2, 0, 0}, {0.7, 0.1, 0.2}));
	const auto s3 = t.addFrontScan({{5, 5, 1}});  // no odometry at all in between
	EXPECT_FALSE(s3.incrementKnown);
}

TEST(CarmenOdometryTracker, RearScanAnchorSplitsTheIncrement)
{
	CCarmenOdometryTracker t;
	const TPose2D front0{0, 0, 0}, rear{1, 0, 0.1};
	t.addFrontScan({front0});
	t.addOdometry(front0, 0, 0);  // anchor
	t.addOdometry({0.9, 0, 0.1}, 0, 0);  // raw
	t.addRearScan({rear});
	EXPECT_TRUE(t.addOdometry(rear, 0, 0));  // anchor after the rear scan
	t.addOdometry({1.5, 0.2, 0.2}, 0, 0);
	const auto s1 = t.addFrontScan({{2, 0, 0}});
	ASSERT_TRUE(s1.incrementKnown);
	const auto expected = mrpt::poses::CPose2D(handIncrement(front0, {0.9, 0, 0.1})) +
						  mrpt::poses::CPose2D(handIncrement(rear, {1.5, 0.2, 0.2}));
	expectPose(s1.increment, expected.asTPose());
}
