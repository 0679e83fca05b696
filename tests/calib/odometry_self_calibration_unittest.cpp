/* hslam tests: COdometrySelfCalibration on hand-derived intervals: the
 * distance scale and UMBmark factors it fits, its prior, its outlier test. */
#include <gtest/gtest.h>
#include <hslam/calib/COdometrySelfCalibration.h>

#include <cmath>
#include <iostream>
#include <random>

using namespace hslam::calib;
using mrpt::poses::CPose2D;

namespace
{
TOdometrySelfCalibration options(bool heading = false, double prior_m = 10.0)
{
	TOdometrySelfCalibration o;
	o.estimate_heading = heading;
	o.prior_travel_m = prior_m;
	o.min_scale_error = 0;  // applied at once (the band has its own test)
	o.rebase_travel_m = 0;  // one fit over all intervals (re-basing has its own test)
	return o;
}
}  // namespace

TEST(OdometrySelfCalibration, FitsTheDistanceScaleWithThePriorAsTravel)
{
	// Odometry reports 0.5 m where the robot drove 0.475 m (Es = 0.95). The
	// fit is (sum of matched distance + prior) / (sum of odometric distance +
	// prior) with unit weights per metre: after 40 m against a 10 m prior,
	// (38 + 10) / (40 + 10) = 0.96.
	COdometrySelfCalibration c(options(), 0.335);
	for (int i = 0; i < 80; ++i) c.observe(CPose2D(0.5, 0, 0), CPose2D(0.475, 0, 0));
	EXPECT_NEAR(c.state().distance_scale, 48.0 / 50.0, 1e-9);
	EXPECT_NEAR(c.state().travel_m, 40.0, 1e-9);
	EXPECT_EQ(c.state().intervals, 80u);
	// Applied: both wheels scaled by a, the heading untouched.
	const CPose2D corrected = c.correct(CPose2D(1.0, 0, 0));
	EXPECT_NEAR(corrected.x(), 0.96, 1e-9);
	EXPECT_NEAR(corrected.phi(), 0.0, 1e-12);
	EXPECT_NEAR(c.state().correction.left_factor, 0.96, 1e-9);
	EXPECT_NEAR(c.state().correction.right_factor, 0.96, 1e-9);
	// Reversing counts the same way (signed distances).
	for (int i = 0; i < 80; ++i) c.observe(CPose2D(-0.5, 0, 0), CPose2D(-0.475, 0, 0));
	EXPECT_NEAR(c.state().distance_scale, (76.0 + 10.0) / (80.0 + 10.0), 1e-9);
}

TEST(OdometrySelfCalibration, KeepsTheNominalCalibrationWithoutEvidence)
{
	COdometrySelfCalibration c(options(), 0.335);
	EXPECT_DOUBLE_EQ(c.state().distance_scale, 1.0);
	const CPose2D step(0.3, 0.02, 0.1);
	EXPECT_EQ(c.correct(step), step) << "nothing fitted yet: identity";
	// Turning on the spot says nothing about the distance scale.
	for (int i = 0; i < 50; ++i) c.observe(CPose2D(0, 0, 0.5), CPose2D(0, 0, 0.45));
	EXPECT_NEAR(c.state().distance_scale, 1.0, 1e-12);
	// Disabled: never corrects.
	auto off = options();
	off.enabled = false;
	COdometrySelfCalibration d(off, 0.335);
	d.observe(CPose2D(0.5, 0, 0), CPose2D(0.4, 0, 0));
	EXPECT_EQ(d.state().intervals, 0u);
	EXPECT_EQ(d.correct(step), step);
}

TEST(OdometrySelfCalibration, RejectsIntervalsTheModelCannotExplain)
{
	// A wheel slipping on a threshold (the odometry says 0.5 m, the robot
	// stood still) or a long interval after failed matches: not evidence.
	COdometrySelfCalibration c(options(), 0.335);
	for (int i = 0; i < 20; ++i) c.observe(CPose2D(0.5, 0, 0), CPose2D(0.5 * 0.97, 0, 0));
	const double before = c.state().distance_scale;
	c.observe(CPose2D(0.5, 0, 0), CPose2D(0.0, 0, 0));  // residual 0.5 > 0.25 * 0.5 + 0.02
	c.observe(CPose2D(5.0, 0, 0), CPose2D(4.0, 0, 0));  // beyond max_interval_m = 2
	EXPECT_EQ(c.state().outliers, 1u);
	EXPECT_EQ(c.state().intervals, 20u);
	EXPECT_DOUBLE_EQ(c.state().distance_scale, before);
	// The factors stay inside TOdometryCorrection's range however far the data go.
	for (int i = 0; i < 2000; ++i) c.observe(CPose2D(0.5, 0, 0), CPose2D(0.5 * 0.85, 0, 0));
	EXPECT_DOUBLE_EQ(c.state().distance_scale, 0.9);
}

TEST(OdometrySelfCalibration, RecoversUmbmarkFactorsFromArcs)
{
	// A robot with c_L = 0.97, c_R = 0.99 and Eb = 1.02 (the truth) driving
	// random arcs: the nominal odometry is integrated with factors 1; the
	// "fused" increments are the true arcs with 1 mm / 0.05 deg noise.
	const double b = 0.335, cL = 0.97, cR = 0.99, Eb = 1.02;
	TOdometryCorrection truth;
	truth.enabled = true, truth.left_factor = cL, truth.right_factor = cR, truth.wheelbase_ratio = Eb;
	const COdometryCorrection actual(truth);
	COdometrySelfCalibration c(options(true, 1.0), b);
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> ds(0.05, 0.6), dphi(-0.6, 0.6);
	std::normal_distribution<double> n(0, 1);
	for (int i = 0; i < 2000; ++i)
	{
		const CPose2D nominal = arcIncrement(ds(rng), dphi(rng));
		const CPose2D moved = actual.correctIncrement(nominal);
		c.observe(nominal, CPose2D(moved.x() + 1e-3 * n(rng), moved.y() + 1e-3 * n(rng),
								   moved.phi() + 0.05 * M_PI / 180 * n(rng)));
	}
	const auto& f = c.state().correction;
	EXPECT_NEAR(f.left_factor, cL, 0.003);
	EXPECT_NEAR(f.right_factor, cR, 0.003);
	EXPECT_NEAR(f.wheelbase_ratio, Eb, 0.003);
	EXPECT_EQ(c.state().outliers, 0u);
}

TEST(OdometrySelfCalibration, AppliesOnlyScaleErrorsBeyondTheFrontEndsOwnBias)
{
	// A 1 % disagreement (the front-end's own bias on exact odometry) is
	// fitted but not applied; a 5 % one is, and stays applied.
	auto o = options();
	o.min_scale_error = 0.02;
	COdometrySelfCalibration c(o, 0.335);
	const CPose2D step(0.5, 0, 0);
	for (int i = 0; i < 400; ++i) c.observe(step, CPose2D(0.495, 0, 0));
	EXPECT_NEAR(c.state().distance_scale, (198.0 + 10.0) / 210.0, 1e-9);
	EXPECT_FALSE(c.state().correction.enabled);
	EXPECT_EQ(c.correct(step), step);
	for (int i = 0; i < 400; ++i) c.observe(step, CPose2D(0.475, 0, 0));
	EXPECT_TRUE(c.state().correction.enabled);
	EXPECT_NEAR(c.correct(step).x(), 0.5 * c.state().distance_scale, 1e-9);
	for (int i = 0; i < 4000; ++i) c.observe(step, CPose2D(0.495, 0, 0));
	EXPECT_GT(c.state().distance_scale, 0.98);
	EXPECT_TRUE(c.state().correction.enabled) << "once detected, the calibration stays applied";
}

TEST(OdometrySelfCalibration, RebasingReachesTheScaleTheMatchesFixOnlyInPart)
{
	// The matches fix half of each interval's distance; the other half follows
	// the odometry as corrected at the time (the fused increment leans towards
	// its prediction): fused = (0.5 * 0.95 + 0.5 * a) * 0.5 m for 0.5 m of
	// odometry, a the scale applied. The fixed point is the true 0.95.
	auto run = [](double rebase_m) {
		auto o = options();
		o.rebase_travel_m = rebase_m;
		COdometrySelfCalibration c(o, 0.335);
		const CPose2D step(0.5, 0, 0);
		for (int i = 0; i < 800; ++i)  // 400 m
		{
			const double applied = c.correct(step).x() / 0.5;
			c.observe(step, CPose2D((0.5 * 0.95 + 0.5 * applied) * 0.5, 0, 0));
		}
		return c.state();
	};
	const auto once = run(0), rebased = run(20);
	// one fit over the run averages in the early, uncorrected intervals:
	// 0.958 after 400 m (hand iteration of the same sums)
	EXPECT_NEAR(once.distance_scale, 0.9579, 5e-4);
	EXPECT_EQ(once.rebases, 0u);
	// re-based every 20 m, each stretch halves the rest of the way
	EXPECT_NEAR(rebased.distance_scale, 0.95, 5e-4);
	EXPECT_EQ(rebased.rebases, 20u);
	// a re-base does not move the scale by itself
	auto o = options();
	o.rebase_travel_m = 1.0;
	COdometrySelfCalibration c(o, 0.335);
	c.observe(CPose2D(0.5, 0, 0), CPose2D(0.45, 0, 0));
	const double beforeRebase = c.state().distance_scale;
	c.observe(CPose2D(0.5, 0, 0), CPose2D(0.45, 0, 0));  // 1 m reached: re-based after this fit
	EXPECT_EQ(c.state().rebases, 1u);
	EXPECT_LT(c.state().distance_scale, beforeRebase);
	const double atRebase = c.state().distance_scale;
	c.observe(CPose2D(0, 0, 0.5), CPose2D(0, 0, 0.5));  // no distance: the fit stays at the base
	EXPECT_NEAR(c.state().distance_scale, atRebase, 1e-12);
}

namespace
{
/** Feeds `n` random arcs of a robot whose odometry gains `curvature_rad_per_m`
 * of heading per metre it does not turn (unequal wheels); the fused heading
 * change carries `noise_rad` of noise per interval. */
void driveCurvedArcs(COdometrySelfCalibration& c, int n, double curvature_rad_per_m, double noise_rad, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> ds(0.2, 0.6), dphi(-0.4, 0.4);
	std::normal_distribution<double> noise(0, noise_rad);
	for (int i = 0; i < n; ++i)
	{
		const double s = ds(rng), turn = dphi(rng);
		const CPose2D truth = arcIncrement(s, turn);
		c.observe(arcIncrement(s, turn + curvature_rad_per_m * s), CPose2D(truth.x(), truth.y(), turn + noise(rng)));
	}
}
}  // namespace

TEST(OdometrySelfCalibration, AppliesTheHeadingTermsOnlyOnceTheirFitIsBeyondItsBandAndNoise)
{
	constexpr double kDegPerM = M_PI / 180;
	auto o = options(true);
	o.min_heading_significance = 3;
	// One wheel 2 % larger (Ed = 1.02): 3.4 deg/m, found and applied.
	COdometrySelfCalibration curved(o, 0.335);
	driveCurvedArcs(curved, 400, 3.4 * kDegPerM, 0.2 * kDegPerM, 1);
	EXPECT_TRUE(curved.state().heading_applied);
	// (the 10 m prior of nominal wheels holds it 6 % short after 160 m)
	EXPECT_NEAR(curved.state().curvature_bias_rad_per_m, -3.4 * kDegPerM, 0.3 * kDegPerM);
	const CPose2D straight = arcIncrement(0.5, 0.0);  // the odometry claims straight: the robot turned right
	EXPECT_NEAR(curved.correct(arcIncrement(0.5, 1.7 * kDegPerM)).phi(), 0.0, 0.15 * kDegPerM);
	EXPECT_LT(curved.correct(straight).phi(), -1.5 * kDegPerM);
	// 0.3 deg/m, well measured: inside the band (what nominal wheels fit), not applied.
	COdometrySelfCalibration slight(o, 0.335);
	driveCurvedArcs(slight, 400, 0.3 * kDegPerM, 0.05 * kDegPerM, 2);
	EXPECT_NEAR(slight.state().curvature_bias_rad_per_m, -0.3 * kDegPerM, 0.05 * kDegPerM);
	EXPECT_FALSE(slight.state().heading_applied);
	EXPECT_NEAR(slight.correct(straight).phi(), 0.0, 1e-12);
	// No bias, 3 deg of noise per interval: early fits stray beyond the band,
	// but not beyond three standard errors; without the significance test
	// they are applied (and stay so).
	COdometrySelfCalibration noisy(o, 0.335);
	driveCurvedArcs(noisy, 400, 0.0, 3.0 * kDegPerM, 3);
	EXPECT_FALSE(noisy.state().heading_applied);
	o.min_heading_significance = 0;
	COdometrySelfCalibration unguarded(o, 0.335);
	driveCurvedArcs(unguarded, 400, 0.0, 3.0 * kDegPerM, 3);
	EXPECT_TRUE(unguarded.state().heading_applied);
}

TEST(OdometrySelfCalibration, ScaleSignificanceWaitsForEvidenceBeyondTheNoise)
{
	// The odometry is 1.5 % long, each fused distance carries 3 cm of noise.
	// With the 1 % band alone the scale is applied as soon as the fit first
	// crosses it; asking for two standard errors waits until the intervals
	// pin the scale down, and then applies it all the same.
	auto o = options();
	o.min_scale_error = 0.01;
	COdometrySelfCalibration bandOnly(o, 0.335);
	o.min_scale_significance = 2;
	COdometrySelfCalibration significant(o, 0.335);
	std::mt19937 rng(5);
	std::normal_distribution<double> noise(0, 0.03);
	size_t firstBandOnly = 0, firstSignificant = 0;
	for (size_t i = 1; i <= 3000; ++i)
	{
		const double matched = 0.5 / 1.015 + noise(rng);
		bandOnly.observe(CPose2D(0.5, 0, 0), CPose2D(matched, 0, 0));
		significant.observe(CPose2D(0.5, 0, 0), CPose2D(matched, 0, 0));
		if (!firstBandOnly && bandOnly.state().distance_applied) firstBandOnly = i;
		if (!firstSignificant && significant.state().distance_applied) firstSignificant = i;
	}
	std::cout << "applied after " << firstBandOnly << " intervals (band alone), " << firstSignificant
			  << " (two standard errors)\n";
	ASSERT_GT(firstBandOnly, 0u);
	ASSERT_GT(firstSignificant, 0u);
	EXPECT_LT(firstBandOnly, 50u);  // measured 6
	EXPECT_GT(firstSignificant, 100u);  // measured 229
	EXPECT_NEAR(significant.state().distance_scale, 1 / 1.015, 0.003);
}
