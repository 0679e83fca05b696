/* hslam tests: the whole evaluation (association + ATE + RPE) and its
 * errors for unusable input. */
#include <gtest/gtest.h>
#include <hslam/eval/evaluate_trajectory.h>

#include <mrpt/core/bits_math.h>

#include <stdexcept>
#include <string>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::common::TTrajectory2D;
using mrpt::poses::CPose2D;

TEST(EvaluateTrajectory, RotatedAndShiftedCopyHasZeroAteAndRpe)
{
	const TTrajectory2D ref = fixtures::windingPath(300);  // 29.9 m
	const TTrajectory2D est = fixtures::transformed(ref, CPose2D(5.0, -3.0, mrpt::DEG2RAD(30.0)));

	const TTrajectoryErrors e = evaluateTrajectory(ref, est);
	EXPECT_EQ(e.matched, 300u);
	EXPECT_EQ(e.unmatched_estimate, 0u);
	EXPECT_EQ(e.unmatched_reference, 0u);
	EXPECT_NEAR(e.ate.position_m.rmse, 0.0, 1e-9);
	EXPECT_NEAR(mrpt::RAD2DEG(e.ate.alignment.phi), -30.0, 1e-9);
	ASSERT_EQ(e.rpe.size(), 3u);
	EXPECT_EQ(e.rpe[0].name, "consecutive");
	EXPECT_EQ(e.rpe[1].name, "1m");
	EXPECT_EQ(e.rpe[2].name, "5m");
	EXPECT_EQ(e.rpe[0].errors.pairs(), 299u);
	EXPECT_EQ(e.rpe[1].errors.pairs(), 290u);  // i = 0 .. 289 (10 steps of 0.1 m)
	EXPECT_EQ(e.rpe[2].errors.pairs(), 250u);  // i = 0 .. 249
	for (const auto& r : e.rpe)
	{
		EXPECT_NEAR(r.errors.trans_m.max, 0.0, 1e-9) << r.name;
		EXPECT_NEAR(r.errors.rot_deg.max, 0.0, 1e-9) << r.name;
	}
}

TEST(EvaluateTrajectory, CountsUnmatchedPosesAndUsesOnlyMatchedOnes)
{
	const TTrajectory2D ref = fixtures::straightLine(100, 0.1);
	TTrajectory2D est;
	for (size_t k = 0; k < ref.size(); k += 2) est.push_back(ref[k]);  // half rate
	est.push_back({500.0, {1e3, 1e3, 0}});  // outside the reference: ignored
	const TTrajectoryErrors e = evaluateTrajectory(ref, est);
	EXPECT_EQ(e.matched, 50u);
	EXPECT_EQ(e.unmatched_reference, 50u);
	EXPECT_EQ(e.unmatched_estimate, 1u);
	EXPECT_NEAR(e.ate.position_m.max, 0.0, 1e-12);
	EXPECT_EQ(e.rpe[1].errors.pairs(), 45u);  // matched poses are 0.2 m apart
}

TEST(EvaluateTrajectory, DisjointClocksNameBothInputsAndTimeRanges)
{
	TEvaluationOptions options;
	options.reference_label = "gt.tum";
	options.estimate_label = "run.tum";
	const TTrajectory2D ref = fixtures::straightLine(11, 0.1, 1700000000.0);
	const TTrajectory2D est = fixtures::straightLine(11, 0.1, 0.0);
	try
	{
		evaluateTrajectory(ref, est, options);
		FAIL() << "expected an error";
	}
	catch (const std::runtime_error& e)
	{
		const std::string msg = e.what();
		for (const char* part : {"gt.tum", "run.tum", "[1700000000.000, 1700000001.000]", "[0.000, 1.000]", "clock"})
			EXPECT_NE(msg.find(part), std::string::npos) << part << " not in: " << msg;
		EXPECT_EQ(msg.find('\n'), std::string::npos);
	}
	EXPECT_THROW(evaluateTrajectory({}, est, options), std::runtime_error);
}

TEST(EvaluateTrajectory, RejectsBadOptions)
{
	const TTrajectory2D t = fixtures::straightLine(10, 0.1);
	TEvaluationOptions options;
	options.rpe_distances_m = {1.0, -2.0};
	EXPECT_THROW(evaluateTrajectory(t, t, options), std::invalid_argument);
	options = {};
	options.max_dt_s = -1;
	EXPECT_THROW(evaluateTrajectory(t, t, options), std::invalid_argument);
	EXPECT_EQ(rpeDistanceName(2.5), "2.5m");
}
