#include <gtest/gtest.h>
#include <hslam/slam/COdometryTracker.h>
#include <mrpt/poses/CPosePDFGaussian.h>

using hslam::slam::COdometryTracker;
using mrpt::poses::CPose2D;

namespace
{
mrpt::obs::CObservationOdometry odometryAt(double x, double y, double phi)
{
	mrpt::obs::CObservationOdometry o;
	o.odometry = CPose2D(x, y, phi);
	return o;
}

void expectPose(const CPose2D& p, double x, double y, double phi)
{
	EXPECT_NEAR(p.x(), x, 1e-9);
	EXPECT_NEAR(p.y(), y, 1e-9);
	EXPECT_NEAR(std::remainder(p.phi() - phi, 2 * M_PI), 0.0, 1e-9);
}
}  // namespace

TEST(OdometryTracker, AbsoluteReadingsGiveIncrementsInTheRobotFrame)
{
	COdometryTracker tracker;
	tracker.addOdometryObservation(odometryAt(1.0, 1.0, M_PI / 2));
	EXPECT_TRUE(tracker.takeIncrement().known);  // first reading: origin only, zero motion
	tracker.addOdometryObservation(odometryAt(1.0, 1.5, M_PI / 2));
	tracker.addOdometryObservation(odometryAt(1.0, 2.0, M_PI));
	const auto inc = tracker.takeIncrement();
	ASSERT_TRUE(inc.known);
	expectPose(inc.delta, 1.0, 0.0, M_PI / 2);  // 1 m forward in the robot frame, then a left turn
	expectPose(tracker.takeIncrement().delta, 0, 0, 0);  // nothing since
}

TEST(OdometryTracker, OdometryStartingAfterTheFirstScanIsUnknownMotionForThatInterval)
{
	// aces cut at entry 14: the first scan has no odometry before it, the
	// first reading comes with the second scan while the robot turns 28 deg;
	// reported as zero motion, the turn was rejected as a bad match (NIS 2432).
	COdometryTracker tracker;
	EXPECT_FALSE(tracker.takeIncrement().known);  // first scan: no odometry yet
	tracker.addOdometryObservation(odometryAt(5.0, 2.0, 1.0));
	EXPECT_FALSE(tracker.takeIncrement().known);  // second scan: only an origin since the first
	tracker.addOdometryObservation(odometryAt(5.0, 2.0, 1.5));
	const auto inc = tracker.takeIncrement();
	ASSERT_TRUE(inc.known);  // from here on, increments are measured
	expectPose(inc.delta, 0, 0, 0.5);
}

TEST(OdometryTracker, ActionsAreComposed)
{
	COdometryTracker tracker;
	mrpt::obs::CActionRobotMovement2D a;
	a.poseChange = mrpt::poses::CPosePDFGaussian::Create(mrpt::poses::CPosePDFGaussian(CPose2D(1.0, 0, M_PI / 2)));
	tracker.addAction(a);
	tracker.addAction(a);
	expectPose(tracker.takeIncrement().delta, 1.0, 1.0, M_PI);
}

TEST(OdometryTracker, GapIsUnknownMotionNotZeroMotion)
{
	COdometryTracker tracker;
	tracker.addOdometryObservation(odometryAt(0, 0, 0));
	tracker.takeIncrement();
	tracker.markGap();
	tracker.addOdometryObservation(odometryAt(3, 0, 0));
	const auto inc = tracker.takeIncrement();
	EXPECT_FALSE(inc.known);
	// next interval is known again
	tracker.addOdometryObservation(odometryAt(4, 0, 0));
	const auto next = tracker.takeIncrement();
	EXPECT_TRUE(next.known);
	expectPose(next.delta, 1.0, 0, 0);
}

namespace
{
mrpt::obs::CObservationOdometry odometryAtTime(double t_s, double x)
{
	mrpt::obs::CObservationOdometry o = odometryAt(x, 0, 0);
	o.timestamp = mrpt::Clock::fromDouble(t_s);
	return o;
}
}  // namespace

TEST(OdometryTracker, IncrementsEndAtTheScansTime)
{
	// Readings at 10 s (x = 0) and 11 s (x = 1): a scan at 10.25 s gets the
	// first quarter of that interval, the next scan at 11 s the rest.
	hslam::slam::TOdometryTiming timing;
	COdometryTracker tracker({}, timing);
	tracker.addOdometryObservation(odometryAtTime(10.0, 0.0));
	EXPECT_FALSE(tracker.readingTimeAfter(10.25));  // the pipeline holds the scan
	tracker.addOdometryObservation(odometryAtTime(11.0, 1.0));
	EXPECT_TRUE(tracker.readingTimeAfter(10.25));
	expectPose(tracker.pendingIncrement(10.25).delta, 0.25, 0, 0);
	expectPose(tracker.takeIncrement(10.25).delta, 0.25, 0, 0);
	expectPose(tracker.takeIncrement(11.0).delta, 0.75, 0, 0);
	// Stamped 0.5 s late: the reading stamped 12 s is the pose at 11.5 s.
	timing.offset_s = 0.5;
	COdometryTracker late({}, timing);
	late.addOdometryObservation(odometryAtTime(10.5, 0.0));
	late.addOdometryObservation(odometryAtTime(12.0, 1.5));
	expectPose(late.takeIncrement(10.5).delta, 0.5, 0, 0);  // 10.0 -> 10.5 s of 10.0 -> 11.5 s
	timing.interpolate = false;  // the last reading before the scan, whatever its time
	COdometryTracker plain({}, timing);
	plain.addOdometryObservation(odometryAtTime(10.0, 0.0));
	plain.addOdometryObservation(odometryAtTime(11.0, 1.0));
	expectPose(plain.takeIncrement(10.25).delta, 1.0, 0, 0);
	EXPECT_TRUE(plain.readingTimeAfter(30.0));  // nothing to wait for
}
