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
	std::vector<double> maxima(400, 20.0);
	for (int i = 0; i < 3; ++i) maxima[i] = 79.0;  // 1 % of 400 = 4 scans needed
	auto limits = deriveCarmenRangeLimits(maxima, 50.0, 0.0);
	EXPECT_FALSE(limits.noReturn_m.has_value());
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 50.0);
	EXPECT_TRUE(limits.isValid(79.0));
	limits = deriveCarmenRangeLimits(maxima, std::nullopt, 0.0);
	EXPECT_DOUBLE_EQ(limits.maxRange_m, 79.0);
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
