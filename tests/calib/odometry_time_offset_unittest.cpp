/* hslam tests: COdometryTimeOffset on a synthetic robot that turns now and
 * then: its odometry stamped late by a known offset, its matched headings
 * exact (or off by noise); the fitted offset against the truth. */
#include <gtest/gtest.h>
#include <hslam/calib/COdometryTimeOffset.h>

#include <cmath>
#include <random>

using namespace hslam::calib;

namespace
{
/** Heading (rad) at time t (s): 90 deg turns of 2 s every 10 s, 45 deg/s. */
double headingAt(double t_s)
{
	const double cycle = std::fmod(t_s, 10.0), turns = std::floor(t_s / 10.0);
	return turns * M_PI / 2 + (cycle < 8.0 ? 0.0 : (cycle - 8.0) / 2.0 * M_PI / 2);
}

/** Feeds `seconds` of odometry (10 Hz, stamped late by lag_s) and matched
 * headings (5 Hz, std noise_rad) in time order; returns the estimator. */
COdometryTimeOffset fed(double lag_s, double seconds, double noise_rad, const TOdometryTimeOffsetOptions& o = {})
{
	COdometryTimeOffset fit(o);
	std::mt19937 rng(7);
	std::normal_distribution<double> noise(0.0, noise_rad);
	for (int k = 0; k * 0.1 <= seconds; ++k)
	{
		const double t = k * 0.1;  // both sensors are read now
		fit.addReading(t, mrpt::poses::CPose2D(0, 0, headingAt(t - lag_s)));  // the pose of lag_s ago
		if (k % 2 == 0) fit.addMatchedHeading(t, headingAt(t) + noise(rng));
	}
	return fit;
}
}  // namespace

TEST(OdometryTimeOffset, LateOdometryIsFoundWithin20Ms)
{
	for (const double lag : {0.3, 0.12, -0.2})
	{
		const auto fit = fed(lag, 60.0, 0.002);
		const auto e = fit.estimate(0.0);
		ASSERT_TRUE(e.has_value());
		EXPECT_NEAR(e->offset_s, lag, 0.02) << "lag " << lag;  // 0.12 s: 0.106 (10 Hz readings round the turns' corners)
		EXPECT_LT(e->cost_ratio, 0.3) << "lag " << lag;  // a clear minimum against no offset
		ASSERT_TRUE(fit.offsetToApply(0.0).has_value());
		EXPECT_NEAR(*fit.offsetToApply(0.0), lag, 0.02);
		EXPECT_FALSE(fit.offsetToApply(lag).has_value());  // already in use
	}
}

TEST(OdometryTimeOffset, OdometryOnTimeIsLeftAlone)
{
	const auto fit = fed(0.0, 60.0, 0.01);  // 0.6 deg of matching noise per heading
	const auto e = fit.estimate(0.0);
	ASSERT_TRUE(e.has_value());
	EXPECT_NEAR(e->offset_s, 0.0, 0.02);
	EXPECT_FALSE(fit.offsetToApply(0.0).has_value());
}

TEST(OdometryTimeOffset, NothingIsAppliedBeforeEnoughRotationWasSeen)
{
	// 7 s: no turn yet; 9 s: half of the first turn (45 deg < min_rotation 90 deg)
	EXPECT_FALSE(fed(0.3, 7.0, 0.002).offsetToApply(0.0).has_value());
	EXPECT_FALSE(fed(0.3, 9.0, 0.002).offsetToApply(0.0).has_value());
	EXPECT_TRUE(fed(0.3, 11.0, 0.002).offsetToApply(0.0).has_value());
	TOdometryTimeOffsetOptions off;
	off.estimate_offset = false;
	EXPECT_FALSE(fed(0.3, 60.0, 0.002, off).offsetToApply(0.0).has_value());
}

TEST(OdometryTimeOffset, OneReadingPerMatchIsNotEnoughToTell)
{
	// Odometry read only when a scan is matched (as the CARMEN imports give
	// it): a shifted reading blends neighbouring steps, not a clock. The same
	// late robot as above, readings at 5 Hz with the matches.
	COdometryTimeOffset fit{TOdometryTimeOffsetOptions{}};
	for (int k = 0; k * 0.2 <= 60.0; ++k)
	{
		const double t = k * 0.2;
		fit.addReading(t, mrpt::poses::CPose2D(0, 0, headingAt(t - 0.3)));
		fit.addMatchedHeading(t, headingAt(t));
	}
	ASSERT_TRUE(fit.estimate(0.0).has_value());
	EXPECT_NEAR(fit.estimate(0.0)->readings_per_pair, 1.0, 0.01);
	EXPECT_FALSE(fit.offsetToApply(0.0).has_value());
}
