/* hslam tests: RPE pair selection by travelled distance and RPE values for
 * a known heading drift. */
#include <gtest/gtest.h>
#include <hslam/eval/relative_pose_error.h>

#include <mrpt/core/bits_math.h>

#include <stdexcept>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::common::TTrajectory2D;
using mrpt::poses::CPose2D;

TEST(RelativePoseError, PairsOnStraightLineWithTenCentimetreSpacing)
{
	const TTrajectory2D line = fixtures::straightLine(101, 0.1);  // 0 .. 10 m
	const auto pairs1m = pairsByTravelledDistance(line, 1.0);
	const auto pairs5m = pairsByTravelledDistance(line, 5.0);
	EXPECT_EQ(consecutivePairs(101).size(), 100u);
	ASSERT_EQ(pairs1m.size(), 91u);  // i = 0 .. 90
	ASSERT_EQ(pairs5m.size(), 51u);  // i = 0 .. 50
	for (size_t k = 0; k < pairs1m.size(); ++k)
	{
		EXPECT_EQ(pairs1m[k].first, k);
		EXPECT_EQ(pairs1m[k].second, k + 10);
	}
	for (const auto& [i, j] : pairs5m) EXPECT_EQ(j, i + 50);
	EXPECT_TRUE(pairsByTravelledDistance(fixtures::straightLine(31, 0.1), 5.0).empty());  // only 3 m
	EXPECT_THROW(pairsByTravelledDistance(line, 0.0), std::invalid_argument);
}

TEST(RelativePoseError, PairEndsAtFirstPoseReachingTheDistance)
{
	// steps 0.4, 0.4, 0.4, 0.3: from pose 0, 1 m is first reached at pose 3
	// (1.2 m); from pose 1 at pose 4 (1.1 m); from pose 2 only 0.7 m remain
	const TTrajectory2D t = {{0, {0, 0, 0}}, {1, {0.4, 0, 0}}, {2, {0.8, 0, 0}}, {3, {1.2, 0, 0}}, {4, {1.5, 0, 0}}};
	const auto pairs = pairsByTravelledDistance(t, 1.0);
	ASSERT_EQ(pairs.size(), 2u);
	EXPECT_EQ(pairs[0], TIndexPair(0, 3));
	EXPECT_EQ(pairs[1], TIndexPair(1, 4));
}

/* Reference: straight line, 0.5 m steps, heading 0. Estimate: each step is
 * (0.5 m forward, then turn delta = 1 deg), i.e. a constant heading drift.
 * Over n steps the reference motion is (n s, 0, 0) and the estimated one is
 * (s sum_{m<n} cos(m delta), s sum_{m<n} sin(m delta), n delta); the error
 * is their difference (the reference motion has no rotation):
 *   consecutive (n = 1): translation 0, rotation 1 deg
 *   1 m (n = 2): |(s cos(delta) - s, s sin(delta))| = 2 s sin(delta/2)
 *                = sin(0.5 deg) = 0.0087265355 m, rotation 2 deg
 *   5 m (n = 10): s |sin(5 delta)/sin(delta/2) e^{i 4.5 delta} - 10|
 *                = 0.3924017750 m, rotation 10 deg */
TEST(RelativePoseError, ConstantHeadingDriftGivesHandComputedErrors)
{
	const double s = 0.5, delta = mrpt::DEG2RAD(1.0);
	const TTrajectory2D ref = fixtures::straightLine(21, s);  // 10 m
	TTrajectory2D est = ref;
	CPose2D pose;
	for (auto& p : est)
	{
		p.pose = pose.asTPose();
		pose = pose + CPose2D(s, 0, delta);
	}

	const auto consecutive = computeRelativePoseError(ref, est, consecutivePairs(21));
	const auto oneMetre = computeRelativePoseError(ref, est, pairsByTravelledDistance(ref, 1.0));
	const auto fiveMetres = computeRelativePoseError(ref, est, pairsByTravelledDistance(ref, 5.0));

	EXPECT_EQ(consecutive.pairs(), 20u);
	EXPECT_NEAR(consecutive.trans_m.rmse, 0.0, 1e-12);
	EXPECT_NEAR(consecutive.rot_deg.rmse, 1.0, 1e-9);
	EXPECT_NEAR(consecutive.rot_deg.mean, 1.0, 1e-9);

	EXPECT_EQ(oneMetre.pairs(), 19u);
	EXPECT_NEAR(oneMetre.trans_m.rmse, 0.008726535498373935, 1e-12);
	EXPECT_NEAR(oneMetre.trans_m.mean, 0.008726535498373935, 1e-12);
	EXPECT_NEAR(oneMetre.rot_deg.rmse, 2.0, 1e-9);

	EXPECT_EQ(fiveMetres.pairs(), 11u);
	EXPECT_NEAR(fiveMetres.trans_m.rmse, 0.392401775006163, 1e-12);
	EXPECT_NEAR(fiveMetres.trans_m.max, 0.392401775006163, 1e-12);
	EXPECT_NEAR(fiveMetres.rot_deg.mean, 10.0, 1e-9);
}

TEST(RelativePoseError, ErrorIsRelativeMotionDifference)
{
	// reference moves 1 m forward; estimate moves 1 m forward and 0.1 m left, turning 90 deg
	const CPose2D e = relativePoseError(CPose2D(3, 4, 1.0), CPose2D(3 + std::cos(1.0), 4 + std::sin(1.0), 1.0),
										CPose2D(0, 0, 0), CPose2D(1, 0.1, M_PI / 2));
	EXPECT_NEAR(e.x(), 0.0, 1e-12);
	EXPECT_NEAR(e.y(), 0.1, 1e-12);
	EXPECT_NEAR(e.phi(), M_PI / 2, 1e-12);
}
