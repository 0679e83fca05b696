/* The hybrid pose estimator (thesis 4.4-4.5) on a real Pioneer log: aces
 * (440 scans, about 1 m apart) converted by our CARMEN importer, with the
 * corrected poses as ground truth. Issue 3's reference numbers (ATE RMSE
 * after SE(2) alignment): odometry 5.4 m, MRPT icp-slam 1.00 m, rbpf-slam 0.83 m. */
#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <memory>
#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>

using namespace hslam;

namespace
{
using hslam::slam::testing::kDefaultIni;

class AcesLog : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		s_dir = std::make_unique<hslam::testing::CTempDir>();
		slam::testing::convertCarmenReferenceLog("aces", s_dir->path().string());
	}
	static void TearDownTestSuite() { s_dir.reset(); }

	/** Runs the pipeline with `method`; returns its trajectory. */
	static std::unique_ptr<slam::CMappingPipeline> run(const std::string& method, std::vector<std::string> extra = {})
	{
		extra.push_back("pose_estimation.method=" + method);
		const auto cfg = common::loadConfigWithOverrides(kDefaultIni, extra);
		auto pipeline = std::make_unique<slam::CMappingPipeline>(cfg);
		io::CRawlogReader reader(s_dir->path().string() + "/aces.rawlog");
		for (io::TRawlogEntry e; reader.next(e);) pipeline->processEntry(e);
		return pipeline;
	}

	static eval::TTrajectoryErrors score(const common::TTrajectory2D& estimate)
	{
		return eval::evaluateTrajectory(common::readTumFile(s_dir->path().string() + "/aces.tum"), estimate, {});
	}

	static std::unique_ptr<hslam::testing::CTempDir> s_dir;
};
std::unique_ptr<hslam::testing::CTempDir> AcesLog::s_dir;
}  // namespace

TEST_F(AcesLog, DefaultEstimatorBeatsOdometryAndIcpSlam)
{
	const auto pipeline = run("lines+icp");
	const auto odometry = score(pipeline->odometryTrajectory());
	const auto estimate = score(pipeline->trajectory());
	EXPECT_NEAR(odometry.ate.position_m.rmse, 5.42, 0.05);  // the foundation's odometry baseline
	EXPECT_LT(estimate.ate.position_m.rmse, 1.0);  // MRPT icp-slam: 1.00 m (measured 0.55 m)
	EXPECT_LT(estimate.rpe[0].errors.trans_m.rmse, odometry.rpe[0].errors.trans_m.rmse);
	EXPECT_LT(estimate.rpe[0].errors.rot_deg.rmse, odometry.rpe[0].errors.rot_deg.rmse);
	// every scan reports a finite pose and a positive-definite covariance
	for (const auto& e : pipeline->estimates())
	{
		ASSERT_TRUE(std::isfinite(e.estimate.pose.x()) && std::isfinite(e.estimate.pose.phi()));
		ASSERT_GT(e.estimate.covariance.determinant(), 0.0);
	}
}

TEST_F(AcesLog, IcpOnlyBeatsOdometry)
{
	const auto pipeline = run("icp");
	EXPECT_LT(score(pipeline->trajectory()).ate.position_m.rmse, 1.0);  // measured 0.24 m
}

TEST_F(AcesLog, LinesOnlyBeatsOdometry)
{
	// The thesis matcher alone (frame to frame, no map): weaker, but better than
	// dead reckoning on this log (measured 3.1 m vs 5.4 m).
	const auto pipeline = run("lines");
	EXPECT_LT(score(pipeline->trajectory()).ate.position_m.rmse, 4.5);
}

TEST_F(AcesLog, OdometryGapDoesNotMakeTheEstimateDiverge)
{
	// Odometry removed around scans 200-201 (about 2 m of travel) and marked as
	// a gap, as our CARMEN importer does: the UKF predicts zero motion with a
	// large covariance and ICP must re-acquire the pose from the map.
	const auto cfg = common::loadConfigWithOverrides(kDefaultIni, {});
	slam::CMappingPipeline pipeline(cfg);
	io::CRawlogReader reader(s_dir->path().string() + "/aces.rawlog");
	size_t scans = 0, dropped = 0;
	// After the gap the odometry chain is re-anchored the way our CARMEN
	// importer does it: the first increment after the gap is only the motion
	// after the gap. new = lastKept (+) (lastDropped^-1 (+) odometry).
	std::optional<mrpt::poses::CPose2D> lastKept, lastDropped;
	for (io::TRawlogEntry e; reader.next(e);)
	{
		if (e.observation && IS_CLASS(*e.observation, mrpt::obs::CObservation2DRangeScan)) ++scans;
		auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(e.observation);
		if (odo && scans >= 199 && scans <= 201)
		{
			++dropped;
			lastDropped = odo->odometry;
			auto marker = mrpt::obs::CObservationComment::Create();
			marker->text = slam::COdometryTracker::kGapMarker;
			marker->timestamp = odo->timestamp;
			e.observation = marker;
		}
		else if (odo && lastDropped)
			odo->odometry = *lastKept + ((-*lastDropped) + odo->odometry);
		else if (odo)
			lastKept = odo->odometry;
		pipeline.processEntry(e);
	}
	ASSERT_GE(dropped, 2u);
	EXPECT_GE(pipeline.counters().odometry_gaps, 2u);
	const auto errors = score(pipeline.trajectory());
	EXPECT_LT(errors.ate.position_m.rmse, 1.5);  // without the gap: 0.55 m; odometry alone: 5.4 m
	EXPECT_LT(errors.ate.position_m.max, 3.0);
}

namespace
{
/** ATE (m) of the front-end (online) and of the whole default pipeline on
 * aces whose odometry readings repeat the one of scan `first` up to scan
 * `last` and then resume (a driver that stalls, then reports the motion made
 * meanwhile in one step), or that are all zero when `first` is 0 and `last`
 * is past the end (a laser-only log). */
std::pair<double, double> ateWithFrozenOdometry(const std::string& logDir, size_t first, size_t last,
												 bool standstillSeed, size_t skippedScans = 0)
{
	std::optional<mrpt::poses::CPose2D> frozen;
	// without the standstill seed, also without the rules that now reach the
	// same where readings froze after motion (the zeros' unknown motion)
	const std::vector<std::string> withoutSeed = {"pose_estimation.standstill_seed_after_gap=false",
												  "motion_prior.zeros_after_motion_unknown=false",
												  "pose_estimation.unconstrained_axis_after_freeze=false"};
	const auto pipeline = slam::testing::runWithRewrittenOdometry(
		logDir + "/aces.rawlog", standstillSeed ? std::vector<std::string>{} : withoutSeed,
		[&](mrpt::poses::CPose2D& odometry, size_t scans) {
			if (scans < first || scans > last) return;
			if (!frozen) frozen = first == 0 ? mrpt::poses::CPose2D() : odometry;
			odometry = *frozen;
		},
		skippedScans);
	const auto reference = common::readTumFile(logDir + "/aces.tum");
	return {eval::evaluateTrajectory(reference, pipeline->trajectory(), {}).ate.position_m.rmse,
			eval::evaluateTrajectory(reference, pipeline->finalTrajectory(), {}).ate.position_m.rmse};
}
}  // namespace

TEST_F(AcesLog, OdometryFrozenForTenScansIsRecoveredByTheStandstillSeed)
{
	// Readings frozen for scans 88-98 (about 30 s and 10 m of travel at this
	// log's spacing of a scan per 2-3 s), then resuming with the motion made
	// meanwhile. The constant velocity measured before the fault carries the
	// estimate on for up to 8 s between scans while the robot turned or
	// stopped; ICP from there settles in a wrong basin that pairs most points
	// ("good"). ICP also seeded where the last match left the robot (the
	// robot stopped) finds the right one by its fit.
	const auto [onlineWith, with] = ateWithFrozenOdometry(s_dir->path().string(), 88, 98, true);
	const auto [onlineWithout, without] = ateWithFrozenOdometry(s_dir->path().string(), 88, 98, false);
	std::cout << "frozen readings, ATE online / final with the standstill seed: " << onlineWith << " / " << with
			  << " m, without: " << onlineWithout << " / " << without << " m\n";
	// Zeros after motion are now unknown motion too (the same two seeds from
	// the first zero), which alone gives 0.097 m: "without" switches it off.
	EXPECT_LT(with, 0.15);  // measured 0.097 m; with odometry throughout 0.098 m
	EXPECT_LT(onlineWith, 1.5);  // measured 0.28 m (0.93 before the zeros' rule; the back-end closes the rest)
	EXPECT_GT(without, 2.0);  // measured 12.6 m (online 12.6 m)
}

TEST_F(AcesLog, LaserOnlyIsTrackedBetterThanTheFrozenOdometry)
{
	// Every reading zero (a robot whose wheel encoders are not read): ICP
	// alone carries the robot over steps of about 1 m and up to 78 deg.
	// A laser-only run is decided by a few steps down corridors where the
	// scan fits a stop about as well as the motion (docs/pose-estimation.md,
	// "The refused track's seed"), so the log is also started later: from
	// scan 125 the estimate was 2.37 m off while the standstill seed's result
	// was taken for the refused track's (counted as a refusal, it measured
	// the velocity: 0.76 -> 0.13 m/s at t = 967 s).
	const std::string dir = s_dir->path().string();
	const auto [onlineWith, with] = ateWithFrozenOdometry(dir, 0, 100000, true);
	const auto [onlineWithout, without] = ateWithFrozenOdometry(dir, 0, 100000, false);
	const auto [onlineLater, later] = ateWithFrozenOdometry(dir, 0, 100000, true, 124);
	std::cout << "laser only, ATE online / final with the standstill seed: " << onlineWith << " / " << with
			  << " m, without: " << onlineWithout << " / " << without << " m; from scan 125: " << onlineLater
			  << " / " << later << " m\n";
	// measured 3.02 m: down a corridor at t = 154.6 s the standstill seed's
	// result 0.19 m back fitted 0.742, the line seed's 1.04 m ahead (truth
	// 1.10) 0.736, and the estimate stalled for 20 s (0.27 m while the
	// refused-track index was wrong, by luck); the frozen odometry's 19.9 m
	EXPECT_LT(with, 4.0);
	EXPECT_LT(later, 1.5);  // measured 1.00 m (2.37 m with the wrong refused-track index)
	EXPECT_GT(without, 10.0);  // measured 11.6 m (27.3 m before the heading cap: worse than no motion at all)
}

namespace
{
/** The whole default pipeline (plus `overrides`) on aces whose every
 * odometry increment is 1 % of the log's (a driver reporting a creeping
 * fraction of the motion, odometry in the wrong units). */
std::unique_ptr<slam::CMappingPipeline> runWithCreepingOdometry(const std::string& logDir,
															  const std::vector<std::string>& overrides)
{
	std::optional<mrpt::poses::CPose2D> previousRead, previousWritten;
	return slam::testing::runWithRewrittenOdometry(
		logDir + "/aces.rawlog", overrides, [&](mrpt::poses::CPose2D& odometry, size_t) {
			const mrpt::poses::CPose2D read = odometry;
			if (previousRead)
			{
				const mrpt::poses::CPose2D d = read - *previousRead;
				odometry = *previousWritten + mrpt::poses::CPose2D(0.01 * d.x(), 0.01 * d.y(), 0.01 * d.phi());
			}
			previousRead = read, previousWritten = odometry;
		});
}
}  // namespace

TEST_F(AcesLog, CreepingOdometryIsFoundAndASecondPassWithItsScaleBeatsIt)
{
	// Every reading 1 % of the motion (issue 12's "laser only" log: wheel
	// readings nearly constant, not zero). The stall rule replaces them
	// where the scans show the disagreement, but the estimate ends worse
	// than the readings themselves. The scale check finds the readings 1 %
	// of the matched motion; rescaled from the start (the second pass
	// hslam-process makes, [odometry_scale_check] rescale and second_pass),
	// the log is tracked as with its own readings.
	const std::string dir = s_dir->path().string();
	const auto reference = common::readTumFile(dir + "/aces.tum");
	const auto ate = [&](const common::TTrajectory2D& t) { return eval::evaluateTrajectory(reference, t, {}).ate.position_m.rmse; };
	const auto first = runWithCreepingOdometry(dir, {"odometry_scale_check.rescale=false"});  // found, not applied
	const auto& check = first->odometryScaleCheck();
	const double odometry = ate(first->odometryTrajectory()), without = ate(first->finalTrajectory());
	ASSERT_TRUE(check.applying());
	EXPECT_NEAR(check.distance().scale, 100.0, 5.0);  // measured 97.4
	EXPECT_NEAR(check.turn().scale, 100.0, 5.0);  // measured 100.2
	const auto second = runWithCreepingOdometry(
		dir, {"odometry_scale_check.distance_scale=" + std::to_string(check.distance().scale),
			  "odometry_scale_check.turn_scale=" + std::to_string(check.turn().scale)});
	const double with = ate(second->finalTrajectory());
	std::cout << "creeping readings, ATE " << without << " m, with the scales found (" << check.distance().scale << ", "
			  << check.turn().scale << ") " << with << " m; the readings " << odometry << " m\n";
	EXPECT_GT(without, odometry);  // measured 24.1 m against 19.7: this test can fail
	EXPECT_LT(with, 0.3);  // measured 0.080 m (0.098 with the readings as logged)
}

namespace
{
/** Length of the first step of `estimate` minus that of the reference at the same stamps (m). */
double firstStepLengthError(const common::TTrajectory2D& estimate, const common::TTrajectory2D& reference)
{
	const auto at = [&reference](double t) {
		return *std::min_element(reference.begin(), reference.end(), [t](const auto& a, const auto& b) {
			return std::abs(a.t_s - t) < std::abs(b.t_s - t);
		});
	};
	const auto length = [](const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b) {
		return std::hypot(b.x - a.x, b.y - a.y);
	};
	return length(estimate[0].pose, estimate[1].pose) - length(at(estimate[0].t_s).pose, at(estimate[1].t_s).pose);
}
}  // namespace

TEST_F(AcesLog, StartedWhileMovingTheFirstStepIsFoundByTheGapSearch)
{
	// aces cut at entry 350 (as scripts/offset-ensemble.sh does with MRPT's
	// rawlog-edit): no odometry before the first scan, so the first step
	// (1.10 m) is unknown motion, predicted as none. ICP from there settled
	// 0.98 m short; the gap search ([gap_search]) finds it.
	const auto firstStepError = [](bool gapSearch) {
		const auto cfg = common::loadConfigWithOverrides(
			kDefaultIni, {std::string("gap_search.enabled=") + (gapSearch ? "true" : "false")});
		slam::CMappingPipeline pipeline(cfg);
		io::CRawlogReader reader(s_dir->path().string() + "/aces.rawlog");
		size_t index = 0;
		for (io::TRawlogEntry e; reader.next(e) && pipeline.trajectory().size() < 3; ++index)
			if (index >= 350) pipeline.processEntry(e);
		pipeline.finish();
		return firstStepLengthError(pipeline.trajectory(), common::readTumFile(s_dir->path().string() + "/aces.tum"));
	};
	const double withSearch = firstStepError(true), without = firstStepError(false);
	std::cout << "first step error with / without the gap search: " << withSearch << " / " << without << " m\n";
	EXPECT_LT(std::abs(withSearch), 0.1);  // measured -0.03 m
	EXPECT_GT(std::abs(without), 0.5);  // the trap: measured -0.98 m
}
