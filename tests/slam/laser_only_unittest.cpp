/* A recording without any odometry (laser only, like the legs dataset) must
 * still be tracked by scan matching: motion is unknown, not zero. Simulated
 * lab sample with its odometry removed, scored against its ground truth. */
#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CObservationOdometry.h>

using namespace hslam;

namespace
{
const std::string kSample = std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/lab";

double ateWithoutOdometry(const std::string& method)
{
	const auto cfg = common::loadConfigWithOverrides(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini",
													 {"pose_estimation.method=" + method, "process.laser_label=LASER"});
	slam::CMappingPipeline pipeline(cfg);
	io::CRawlogReader reader(kSample + "/sim.rawlog");
	for (io::TRawlogEntry e; reader.next(e);)
		if (!(e.observation && IS_CLASS(*e.observation, mrpt::obs::CObservationOdometry))) pipeline.processEntry(e);
	EXPECT_EQ(pipeline.counters().odometry_readings, 0u);
	const auto errors =
		eval::evaluateTrajectory(common::readTumFile(kSample + "/ground_truth.tum"), pipeline.trajectory(), {});
	return errors.ate.position_m.rmse;
}
}  // namespace

TEST(LaserOnlyLog, ScanMatchingTracksTheRobotWithoutOdometry)
{
	// Dead reckoning without odometry stays at the start: metres of error.
	EXPECT_GT(ateWithoutOdometry("odometry"), 1.0);
	EXPECT_LT(ateWithoutOdometry("icp"), 0.1);
	EXPECT_LT(ateWithoutOdometry("lines+icp"), 0.1);
}
