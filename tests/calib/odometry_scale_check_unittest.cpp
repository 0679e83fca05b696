/* COdometryScaleCheck: odometry reporting a gross fraction or multiple of the
 * matched motion is found (distance and turn separately) and rescaled only
 * once both are judged; readings at their own scale, exact zeros and
 * scattered ratios are left alone. Hand-derived intervals. */
#include <gtest/gtest.h>
#include <hslam/calib/COdometryScaleCheck.h>

#include <cmath>

using hslam::calib::COdometryScaleCheck;
using hslam::calib::TOdometryScaleCheck;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

/** `n` intervals of 0.5 m and 20 deg matched, the odometry reporting `k` of each. */
void drive(COdometryScaleCheck& check, int n, double distanceK, double turnK)
{
	for (int i = 0; i < n; ++i)
		check.observe(CPose2D(distanceK * 0.5, 0, turnK * 20 * kDeg), CPose2D(0.5, 0, 20 * kDeg));
}
TOdometryScaleCheck rescaling() { return TOdometryScaleCheck(); }  // rescale is the default
}  // namespace

TEST(OdometryScaleCheck, ReadingsAtOnePercentAreRescaledByAHundredOnceBothAreJudged)
{
	COdometryScaleCheck check(rescaling());
	drive(check, 9, 0.01, 0.01);
	EXPECT_FALSE(check.applying());  // 9 samples of each: not judged yet
	EXPECT_NEAR(check.correct(CPose2D(0.01, 0, 0.01)).x(), 0.01, 1e-12);
	drive(check, 1, 0.01, 0.01);
	ASSERT_TRUE(check.applying());
	EXPECT_NEAR(check.distance().scale, 100.0, 1e-9);
	EXPECT_NEAR(check.turn().scale, 100.0, 1e-9);
	const CPose2D corrected = check.correct(CPose2D(0.005, 0.001, 0.002));
	EXPECT_NEAR(corrected.x(), 0.5, 1e-9);
	EXPECT_NEAR(corrected.y(), 0.1, 1e-9);
	EXPECT_NEAR(corrected.phi(), 0.2, 1e-9);
}

TEST(OdometryScaleCheck, ADistanceOffWithoutTurnsMeasuredIsNotRescaled)
{
	// A long straight start: a distance at 1 % rescaled while turns still
	// read 1 % drove the simulated floor straight past its corners.
	COdometryScaleCheck check(rescaling());
	for (int i = 0; i < 30; ++i) check.observe(CPose2D(0.005, 0, 0), CPose2D(0.5, 0, 0));
	EXPECT_TRUE(check.distance().applied);
	EXPECT_EQ(check.turn().samples, 0u);
	EXPECT_FALSE(check.applying());
	EXPECT_NEAR(check.correct(CPose2D(0.005, 0, 0)).x(), 0.005, 1e-12);
}

TEST(OdometryScaleCheck, ReadingsAtTheirOwnScaleZerosAndScatterAreLeftAlone)
{
	COdometryScaleCheck nominal(rescaling());
	drive(nominal, 50, 1.03, 0.97);  // a few percent off: the self-calibration's business
	EXPECT_FALSE(nominal.distance().applied);
	EXPECT_FALSE(nominal.turn().applied);
	EXPECT_NEAR(nominal.distance().median_ratio, 1.03, 1e-9);

	COdometryScaleCheck zeros(rescaling());
	drive(zeros, 50, 0, 0);  // readings that never move hold no scale
	EXPECT_EQ(zeros.distance().samples, 0u);
	EXPECT_FALSE(zeros.applying());

	COdometryScaleCheck scattered(rescaling());  // half at 1 %, half at 30 %: no factor explains them
	for (int i = 0; i < 20; ++i) drive(scattered, 1, i % 2 ? 0.01 : 0.3, i % 2 ? 0.01 : 0.3);
	EXPECT_FALSE(scattered.applying());
}

TEST(OdometryScaleCheck, ShortIntervalsAreJoinedAndFoundScalesOnlyReportedUnlessRescaling)
{
	// 5 Hz: intervals of 0.1 m and 4 deg make a sample every third one (two
	// turning ones span a chord of 0.1998 m, under 0.2; three turn 12 deg)
	TOdometryScaleCheck reportOnly;
	reportOnly.rescale = false;
	COdometryScaleCheck check(reportOnly);
	for (int i = 0; i < 60; ++i) check.observe(CPose2D(0.001, 0, 0.04 * kDeg), CPose2D(0.1, 0, 4 * kDeg));
	EXPECT_EQ(check.distance().samples, 20u);
	EXPECT_EQ(check.turn().samples, 20u);
	EXPECT_TRUE(check.applying());
	EXPECT_NEAR(check.correct(CPose2D(0.001, 0, 0)).x(), 0.001, 1e-12);  // rescale = false: reported only
	reportOnly.distance_scale = 100, reportOnly.turn_scale = 100;  // a known units error
	EXPECT_NEAR(COdometryScaleCheck(reportOnly).correct(CPose2D(0.001, 0, 0.001)).phi(), 0.1, 1e-12);
}

TEST(OdometryScaleCheck, ReadingsTooCoarseOnceRescaledAreOnlyReported)
{
	// ARCOS units (4096 per turn) creeping at 1 %: rescaled by 100 the
	// readings would turn in 8.8 deg steps
	COdometryScaleCheck coarse(rescaling());
	coarse.noteIncrement(CPose2D(0.001, 0, 2 * M_PI / 4096));
	drive(coarse, 10, 0.01, 0.01);
	EXPECT_TRUE(coarse.distance().applied);
	EXPECT_TRUE(coarse.turn().applied);
	EXPECT_FALSE(coarse.applying());
	EXPECT_NEAR(coarse.correct(CPose2D(0.001, 0, 0)).x(), 0.001, 1e-12);
	// the same in microradians (a CARMEN log's six decimals): fine enough
	COdometryScaleCheck fine(rescaling());
	fine.noteIncrement(CPose2D(1e-6, 0, 1e-6));
	drive(fine, 10, 0.01, 0.01);
	EXPECT_TRUE(fine.applying());
}
