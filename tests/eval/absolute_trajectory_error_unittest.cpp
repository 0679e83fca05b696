/* hslam tests: SE(2) alignment and ATE against hand-computed values. */
#include <gtest/gtest.h>
#include <hslam/eval/absolute_trajectory_error.h>
#include <hslam/eval/se2_alignment.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <stdexcept>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::common::TTrajectory2D;
using mrpt::poses::CPose2D;

TEST(AbsoluteTrajectoryError, RigidlyMovedCopyAlignsExactly)
{
	const TTrajectory2D ref = fixtures::windingPath(200);
	const CPose2D motion(5.0, -3.0, mrpt::DEG2RAD(30.0));
	const TTrajectory2D est = fixtures::transformed(ref, motion);

	const TAbsoluteTrajectoryError ate = computeAbsoluteTrajectoryError(ref, est);
	EXPECT_NEAR(ate.position_m.rmse, 0.0, 1e-9);
	EXPECT_NEAR(ate.position_m.max, 0.0, 1e-9);
	EXPECT_EQ(ate.position_m.count, 200u);
	const CPose2D expected = -motion;  // alignment undoes the motion
	EXPECT_NEAR(ate.alignment.x, expected.x(), 1e-9);
	EXPECT_NEAR(ate.alignment.y, expected.y(), 1e-9);
	EXPECT_NEAR(ate.alignment.phi, mrpt::DEG2RAD(-30.0), 1e-12);
}

/* Square corners r0..r3 = (1,1), (-1,1), (-1,-1), (1,-1); the estimate
 * equals it except e0 = r0 + (a, a).
 * Centroids: reference (0,0), estimate (a/4, a/4). Centred cross terms
 * sum(e' x r') are 0, -a/2, 0, +a/2 -> 0, so the best rotation is 0 and the
 * translation is (-a/4, -a/4). Residuals: pose 0 (3a/4, 3a/4), poses 1-3
 * (-a/4, -a/4), i.e. norms 3a*sqrt(2)/4 and a*sqrt(2)/4.
 *   RMSE = sqrt((9 + 3) * 2 a^2/16 / 4) = a * sqrt(3/8)
 *   mean = (3 + 3) * a*sqrt(2)/4 / 4 = 3 a sqrt(2) / 8
 *   max  = 3 a sqrt(2) / 4
 * With a = 0.4: 0.244948974, 0.212132034, 0.424264069. */
TEST(AbsoluteTrajectoryError, SingleOffsetPoseGivesHandComputedAte)
{
	const double a = 0.4;
	const TTrajectory2D ref = {{0, {1, 1, 0}}, {1, {-1, 1, 2}}, {2, {-1, -1, -1}}, {3, {1, -1, 3}}};
	TTrajectory2D est = ref;
	est[0].pose.x += a;
	est[0].pose.y += a;

	const TAbsoluteTrajectoryError ate = computeAbsoluteTrajectoryError(ref, est);
	EXPECT_NEAR(ate.position_m.rmse, 0.2449489742783178, 1e-12);
	EXPECT_NEAR(ate.position_m.mean, 0.21213203435596428, 1e-12);
	EXPECT_NEAR(ate.position_m.max, 0.42426406871192857, 1e-12);
	EXPECT_NEAR(ate.alignment.x, -a / 4, 1e-12);
	EXPECT_NEAR(ate.alignment.y, -a / 4, 1e-12);
	EXPECT_NEAR(ate.alignment.phi, 0.0, 1e-12);

	// the same estimate in another frame: identical ATE
	const TTrajectory2D moved = fixtures::transformed(est, CPose2D(-7.0, 2.0, mrpt::DEG2RAD(-120.0)));
	EXPECT_NEAR(computeAbsoluteTrajectoryError(ref, moved).position_m.rmse, 0.2449489742783178, 1e-12);
}

TEST(AbsoluteTrajectoryError, RejectsMismatchedInput)
{
	const std::vector<mrpt::math::TPoint2D> two = {{0, 0}, {1, 0}}, one = {{0, 0}};
	EXPECT_THROW(alignPointsSE2(two, one), std::invalid_argument);
	EXPECT_THROW(alignPointsSE2({}, {}), std::invalid_argument);
	// all points equal: translation only, angle 0
	const CPose2D t = alignPointsSE2({{1, 1}, {1, 1}}, {{3, 4}, {3, 4}});
	EXPECT_NEAR(t.x(), 2.0, 1e-12);
	EXPECT_NEAR(t.y(), 3.0, 1e-12);
	EXPECT_NEAR(t.phi(), 0.0, 1e-12);
}
