/* The default front-end on a real log with sparse scans: csail (CARMEN,
 * scans about 1 s apart, turns of 40 deg between two scans), converted by
 * our CARMEN importer, corrected poses as reference. Started at rawlog entry
 * 70 (as scripts/offset-ensemble.sh cuts it with rawlog-edit), the robot
 * turns in place at t = 55 s; ICP's seeds end in two basins 42 deg apart
 * whose fits are 0.403 and 0.330, and the better-fitting one is wrong. Taken
 * at its own 1.6 deg covariance it split the map (front-end ATE 2.18 m);
 * with the covariance widened over both basins (competing_basins.h) the
 * filter keeps the prediction there (0.43 m). The case was found with
 * [icp] engine = mrpt, which the test pins; with the cached engine (the
 * same algorithm to 1e-5) this start happens not to reach the wrong basin
 * (0.64 m with widening, 0.42 m without: single runs of a real log move by
 * that much under numerical changes). */
#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <memory>
#include <optional>
#include <random>
#include <iostream>
#include <mrpt/obs/CObservationOdometry.h>

using namespace hslam;

namespace
{
class CsailLog : public ::testing::Test
{
   protected:
	static void SetUpTestSuite()
	{
		s_dir = std::make_unique<hslam::testing::CTempDir>();
		slam::testing::convertCarmenReferenceLog("csail", s_dir->path().string());
	}
	static void TearDownTestSuite() { s_dir.reset(); }

	/** Front-end alone from rawlog entry `first`; ATE RMSE (m) of its trajectory. */
	static double ateFrom(size_t first, std::vector<std::string> overrides)
	{
		overrides.push_back("loop_closure.enabled=false");
		overrides.push_back("icp.engine=mrpt");
		// the configuration the two-basin case was found in: with the scan's
		// grazing points left out this start slips elsewhere (1.06 m; the
		// default cached engine 0.60 m), which this test is not about
		overrides.push_back("icp.max_incidence_deg=0");
		// and with the odometry as logged: calibrated (2.6 % longer steps)
		// this start reaches the turn elsewhere (0.71 m; 0.49 m without the
		// widening), which this test is not about either
		overrides.push_back("odometry_self_calibration.enabled=false");
		const auto cfg = common::loadConfigWithOverrides(slam::testing::kDefaultIni, overrides);
		slam::CMappingPipeline pipeline(cfg);
		io::CRawlogReader reader(s_dir->path().string() + "/csail.rawlog");
		size_t index = 0;
		for (io::TRawlogEntry e; reader.next(e); ++index)
			if (index >= first) pipeline.processEntry(e);
		const auto reference = common::readTumFile(s_dir->path().string() + "/csail.tum");
		return eval::evaluateTrajectory(reference, pipeline.trajectory(), {}).ate.position_m.rmse;
	}

	static std::unique_ptr<hslam::testing::CTempDir> s_dir;
};
std::unique_ptr<hslam::testing::CTempDir> CsailLog::s_dir;
}  // namespace

TEST_F(CsailLog, FastTurnIsNotTakenFromTheWrongOfTwoBasins)
{
	EXPECT_LT(ateFrom(70, {}), 0.6);  // measured 0.43 m
	// Without the widening, and without restarting a badly fitting first
	// result ([icp] restart_below_fit), the wrong basin is taken at its own
	// covariance.
	// (With the covariance counting information per length of wall, [icp]
	// covariance_full_weight_spacing_m, the wrong basin is not taken either:
	// 0.30 m; the counterfactual counts every beam.)
	// (Nor when a match fitting worse than the prediction is refused,
	// [pose_estimation] max_fit_loss_vs_prediction: the wrong basin fits
	// worse than the prediction; the counterfactual goes without it.)
	EXPECT_GT(ateFrom(70, {"icp.competing_fit_ratio=0", "icp.restart_below_fit=0", "icp.restart_same_basin_m=0",
						   "icp.covariance_full_weight_spacing_m=0", "pose_estimation.max_fit_loss_vs_prediction=-1"}),
			  1.5);  // measured 2.18 m (with the far seeds skipped when the near ones agree: 0.35 m)
	// Either rule alone avoids it: the restart finds the better-fitting basin.
	EXPECT_LT(ateFrom(70, {"icp.competing_fit_ratio=0"}), 0.6);  // measured 0.38 m
}

namespace
{
/** ATE (m) of the front-end (online) on the converted CARMEN log `name`
 * in `logDir` whose odometry increments get the noise of
 * scripts/perturb_carmen_log.py's "noisy" variant, drawn from `seed`: 10 %
 * of the distance forward, 0.05 m/m sideways, and 0.05 rad/m plus
 * `turnStdPerRad` of the turn in heading (the readings after it composed on). */
double onlineAteWithNoisyOdometry(const std::string& logDir, const std::string& name, double turnStdPerRad,
								  unsigned seed, const std::vector<std::string>& overrides)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> unit(0.0, 1.0);
	std::optional<mrpt::poses::CPose2D> previousRaw;
	mrpt::poses::CPose2D noisy;
	const auto pipeline = slam::testing::runWithRewrittenOdometry(
		logDir + "/" + name + ".rawlog", overrides, [&](mrpt::poses::CPose2D& odometry, size_t) {
			const mrpt::poses::CPose2D raw = odometry;
			if (previousRaw)
			{
				const mrpt::poses::CPose2D step = raw - *previousRaw;
				const double d = step.norm();
				noisy = noisy + mrpt::poses::CPose2D(step.x() * (1 + 0.1 * unit(rng)), step.y() + 0.05 * d * unit(rng),
													 step.phi() + (0.05 * d + turnStdPerRad * std::abs(step.phi())) * unit(rng));
			}
			else
				noisy = raw;
			previousRaw = raw;
			odometry = noisy;
		});
	return eval::evaluateTrajectory(common::readTumFile(logDir + "/" + name + ".tum"), pipeline->trajectory(), {})
		.ate.position_m.rmse;
}
}  // namespace

TEST_F(CsailLog, OdometryNoisierThanItsModelIsNotFollowed)
{
	// Heading noise of 0.05 rad/m + 0.1 of the turn, on readings a scan
	// apart (turns of up to 78 deg): steps tens of degrees off, several of
	// the model's std. ICP and its heading restarts settled in wrong basins
	// near the prediction, and three matches that contradicted the noisy
	// readings declared a stall, whose constant velocity carried the robot
	// off. The wide search after a poor match ([gap_search]
	// after_poor_match) and a stall that needs readings that creep
	// ([motion_prior] stall_needs_creeping) follow the scans.
	const std::vector<std::string> without{"gap_search.after_poor_match=false",
										   "motion_prior.stall_needs_creeping=false"};
	double worstWith = 0, worstWithout = 0;
	for (unsigned seed : {2u, 3u, 4u})
	{
		const double with = onlineAteWithNoisyOdometry(s_dir->path().string(), "csail", 0.1, seed, {});
		const double off = onlineAteWithNoisyOdometry(s_dir->path().string(), "csail", 0.1, seed, without);
		std::cout << "noisy odometry, draw " << seed << ": online ATE " << with << " m, without the two rules " << off
				  << " m\n";
		worstWith = std::max(worstWith, with), worstWithout = std::max(worstWithout, off);
	}
	EXPECT_LT(worstWith, 0.6);  // measured 0.19 / 0.45 / 0.21 m
	EXPECT_GT(worstWithout, 1.5);  // measured 0.60 / 2.71 / 0.43 m
}
