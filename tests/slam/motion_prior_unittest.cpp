/* CMotionPrior: speeds are judged over min_interval_s at least and never
 * exceed what the robot can do (the intel failure: two scans 20 ms apart made
 * an ordinary increment a "jump" and a matched turn a 29 rad/s velocity). */
#include <gtest/gtest.h>
#include <hslam/slam/CMotionPrior.h>

#include <cmath>

using hslam::slam::CMotionPrior;
using hslam::slam::TMotionPrior;
using hslam::slam::TOdometryIncrement;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

TOdometryIncrement odometry(double x, double y, double phi)
{
	TOdometryIncrement i;
	i.delta = CPose2D(x, y, phi);
	return i;
}
}  // namespace

TEST(MotionPrior, AnOrdinaryIncrementTwentyMillisecondsLaterIsNoJump)
{
	CMotionPrior prior;
	prior.prior(odometry(0, 0, 0), 10.0);
	// 5 cm and 8 deg: 400 deg/s over 20 ms (over max_turn_rate), ordinary over 0.25 s.
	const TMotionPrior p = prior.prior(odometry(0.05, 0, 8 * kDeg), 10.02);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
	// A real jump (2 m in 20 ms, more than max_speed_mps x 0.25 s) still is one.
	const TMotionPrior jump = prior.prior(odometry(2.0, 0, 0), 10.04);
	EXPECT_EQ(jump.reason, "jump");
}

TEST(MotionPrior, VelocityIsMeasuredOverTheMinimumInterval)
{
	CMotionPrior prior;
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.observePose(CPose2D(0.5, 0, 0), 1.0);
	prior.observePose(CPose2D(0.5, 0, 0.58), 1.02);  // a 33 deg correction 20 ms later
	// Over the last 1.02 s (the newest estimate at least 0.25 s old is t = 0):
	// 0.58 rad / 1.02 s, not 0.58 rad / 0.02 s = 29 rad/s.
	EXPECT_NEAR(prior.velocity().z(), 0.58 / 1.02, 1e-9);
	EXPECT_NEAR(prior.velocity().x(), 0.5 / 1.02, 1e-9);
}

TEST(MotionPrior, VelocityNeverExceedsTheRobotsLimits)
{
	CMotionPrior::TOptions o;
	o.max_speed_mps = 1.5;
	o.max_turn_rate_rad_s = 90 * kDeg;
	CMotionPrior prior(o);
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.observePose(CPose2D(3, 4, 2.0), 0.5);  // 10 m/s, 4 rad/s
	EXPECT_NEAR(prior.velocity().head<2>().norm(), 1.5, 1e-9);
	EXPECT_NEAR(prior.velocity().x() / prior.velocity().y(), 3.0 / 4.0, 1e-9);  // direction kept
	EXPECT_NEAR(prior.velocity().z(), 90 * kDeg, 1e-9);
	// The constant-velocity prior over the next second extrapolates at most that.
	TOdometryIncrement gap;
	gap.known = false;
	prior.prior(gap, 0.5);
	const TMotionPrior p = prior.prior(gap, 1.5);
	EXPECT_EQ(p.reason, "gap");
	EXPECT_NEAR(p.delta.norm(), 1.5, 1e-9);
	EXPECT_NEAR(p.delta.phi(), 90 * kDeg, 1e-9);
}

TEST(MotionPrior, UnknownMotionBeforeTheFirstOdometryIsNoStall)
{
	// aces cut at entry 6: no odometry reading before the second scan, which
	// the scans saw turn 44 deg; the next interval has odometry again.
	CMotionPrior prior;
	TOdometryIncrement unknown;
	unknown.known = false;
	prior.prior(unknown, 22.74);
	prior.observePose(CPose2D(0, 0, 0), 22.74);
	EXPECT_EQ(prior.prior(unknown, 23.86).reason, "gap");
	prior.observePose(CPose2D(0.14, -0.11, -43.7 * kDeg), 23.86);
	// the unknown interval is not "odometry read zero while the robot turned"
	const TMotionPrior p = prior.prior(odometry(1.02, -0.05, 6.5 * kDeg), 25.41);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
}

TEST(MotionPrior, StallEvidenceOlderThanTheWindowIsForgotten)
{
	CMotionPrior prior;  // disagreement_window_s = 3
	prior.prior(odometry(0.001, 0, 0), 0.0);
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.prior(odometry(0.001, 0, 0), 1.0);
	prior.observePose(CPose2D(0.5, 0, 0), 1.0);  // the scans moved 0.5 m, odometry 1 mm
	EXPECT_EQ(prior.prior(odometry(0.001, 0, 0), 2.0).reason, "stalled");  // within the window
	prior.observePose(CPose2D(1.0, 0, 0), 2.0);
	// the next scan comes 8 s later: the disagreement at 1-2 s is outside
	// the window ending now, and odometry reports ordinary motion
	const TMotionPrior p = prior.prior(odometry(0.5, 0, 0.1), 10.0);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
}
