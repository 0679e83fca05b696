/* hslam tests: no-return marker detection (deriveCarmenRangeLimits). */
#include <gtest/gtest.h>
#include <hslam/io/carmen_range_limits.h>

using namespace hslam::io;

TEST(CarmenRangeLimits, MarkerFoundWhenItIsTheMaximumOfManyScans)
{
	std::vector<double> maxima(100, 30.0);
	for (int i = 0; i < 3; ++i) maxima[i] = 81.91;  // max(3, 1 % of 100) = 3 scans needed
	maxima[50] = 79.0;
	const auto limits = deriveCarmenRangeLimits(maxima, 50.0, 0.0);
	ASSERT_TRUE(limits.noReturn_m.has_value());
	EXPECT_DOUBLE_EQ(*limits.noReturn_m, 81.91);
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 81.91);
	EXPECT_FALSE(limits.isValid(81.91));
	EXPECT_FALSE(limits.isValid(81.91 - 0.5e-6));
	EXPECT_TRUE(limits.isValid(79.0));  // a real long return stays valid
	EXPECT_FALSE(limits.isValid(0.0));
	EXPECT_FALSE(limits.isValid(-1.0));
}

TEST(CarmenRangeLimits, NoMarkerUsesParamThenGlobalMax)
{
	// Scan maxima all different (no value repeats, so no no-return marker),
	// three long returns among them.
	std::vector<double> maxima(400);
	for (size_t i = 0; i < maxima.size(); ++i) maxima[i] = 10.0 + 0.01 * static_cast<double>(i);
	for (int i = 0; i < 3; ++i) maxima[i] = 79.0 + i;
	auto limits = deriveCarmenRangeLimits(maxima, 50.0, 0.0);
	EXPECT_FALSE(limits.noReturn_m.has_value());
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 50.0);
	EXPECT_TRUE(limits.isValid(79.0));
	limits = deriveCarmenRangeLimits(maxima, std::nullopt, 0.0);
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 81.0);
	EXPECT_NE(limits.reason.find("no no-return marker"), std::string::npos) << limits.reason;
}

TEST(CarmenRangeLimits, UserMaximumOverrides)
{
	const auto limits = deriveCarmenRangeLimits(std::vector<double>(10, 81.91), std::nullopt, 40.0);
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 40.0);
	EXPECT_FALSE(limits.isValid(40.0));
	EXPECT_TRUE(limits.isValid(39.9));
	EXPECT_FALSE(deriveCarmenRangeLimits({}, std::nullopt, 0.0).noReturn_m.has_value());
	EXPECT_EQ(scanMaximum({1.0, 5.0, 2.0}), 5.0);
	EXPECT_FALSE(scanMaximum({}).has_value());
}

TEST(CarmenRangeLimits, OneOutlierBeamDoesNotHideTheMarker)
{
	// Issue 15 item 2: one beam of 1e308 (or 82.5 m in intel, marker 81.91)
	// used to become the "global maximum", seen in one scan only, so no marker
	// was found and every no-return beam became an 80 m wall.
	for (double outlier : {1e308, 82.5})
	{
		std::vector<double> maxima(1000, 30.0);
		for (int i = 0; i < 200; ++i) maxima[i * 5] = 81.91;
		maxima[7] = outlier;
		const auto limits = deriveCarmenRangeLimits(maxima, std::nullopt, 0.0);
		ASSERT_TRUE(limits.noReturn_m.has_value()) << limits.reason;
		EXPECT_DOUBLE_EQ(*limits.noReturn_m, 81.91);
		EXPECT_DOUBLE_EQ(limits.maxRange_m, 81.91);
		EXPECT_EQ(limits.outlierScans, 1u);
		EXPECT_DOUBLE_EQ(limits.largestOutlier_m, outlier);
		EXPECT_FALSE(limits.isValid(outlier));  // the outlier beam itself is dropped
		EXPECT_NE(limits.reason.find("1 scans with larger (outlier) ranges"), std::string::npos) << limits.reason;
	}
}
