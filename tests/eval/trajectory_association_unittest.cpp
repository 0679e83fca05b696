/* hslam tests: timestamp association (jitter, gaps, competition, order). */
#include <gtest/gtest.h>
#include <hslam/eval/trajectory_association.h>

#include <algorithm>
#include <stdexcept>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::common::TTrajectory2D;

TEST(TrajectoryAssociation, JitterMissingPosesAndExtrasGiveExactCounts)
{
	// reference: 50 poses at 10 Hz, x = index
	TTrajectory2D ref = fixtures::straightLine(50, 1.0);
	// estimate: same poses with +-15 ms jitter, poses 3, 17 and 30 missing
	TTrajectory2D est;
	for (int k = 0; k < 50; ++k)
		if (k != 3 && k != 17 && k != 30) est.push_back({100.0 + 0.1 * k + 0.015 * (k % 3 - 1), {1.0 * k, 0, 0}});
	est.push_back({101.05, {-1, 0, 0}});  // 50 ms from refs 10 and 11: unmatched
	est.push_back({200.0, {-1, 0, 0}});  // far after the reference
	est.push_back({102.018, {-1, 0, 0}});  // competes for ref 20 with est 20 (dt 15 ms) and loses
	std::reverse(est.begin(), est.end());  // order must not matter
	std::reverse(ref.begin(), ref.end());

	const TAssociation a = associateByTimestamp(ref, est, 0.02);
	EXPECT_EQ(a.size(), 47u);
	EXPECT_EQ(a.unmatched_estimate, 3u);
	EXPECT_EQ(a.unmatched_reference, 3u);
	for (size_t k = 0; k < a.size(); ++k)
	{
		EXPECT_EQ(a.estimate[k].pose.x, a.reference[k].pose.x) << "pair " << k;
		if (k > 0)
		{
			EXPECT_LT(a.estimate[k - 1].t_s, a.estimate[k].t_s);
		}
	}
}

TEST(TrajectoryAssociation, TakesNearestReferenceNotFirstInWindow)
{
	const TTrajectory2D ref = {{0.000, {0, 0, 0}}, {0.010, {1, 0, 0}}, {0.030, {2, 0, 0}}};
	const TTrajectory2D est = {{0.008, {1, 0, 0}}};
	const TAssociation a = associateByTimestamp(ref, est, 0.02);
	ASSERT_EQ(a.size(), 1u);
	EXPECT_EQ(a.reference[0].pose.x, 1.0);
	EXPECT_EQ(a.unmatched_reference, 2u);
}

TEST(TrajectoryAssociation, EachReferenceUsedOnceEvenIfNearestForTwo)
{
	// both estimates are nearest to ref 1.0; the closer (1.004) gets it, the
	// other falls back to ref 0.99 which is still within max_dt
	const TTrajectory2D ref = {{0.99, {0, 0, 0}}, {1.00, {1, 0, 0}}};
	const TTrajectory2D est = {{0.997, {0, 0, 0}}, {1.002, {1, 0, 0}}};
	const TAssociation a = associateByTimestamp(ref, est, 0.02);
	ASSERT_EQ(a.size(), 2u);
	EXPECT_EQ(a.reference[0].pose.x, 0.0);
	EXPECT_EQ(a.reference[1].pose.x, 1.0);
}

TEST(TrajectoryAssociation, TimeRangeAndBadTolerance)
{
	const TTrajectory2D t = {{5.0, {}}, {2.0, {}}, {9.0, {}}};
	const TTimeRange r = timeRange(t);
	EXPECT_FALSE(r.empty);
	EXPECT_EQ(r.first_s, 2.0);
	EXPECT_EQ(r.last_s, 9.0);
	EXPECT_TRUE(timeRange({}).empty);
	EXPECT_THROW(associateByTimestamp(t, t, -0.1), std::invalid_argument);
}
