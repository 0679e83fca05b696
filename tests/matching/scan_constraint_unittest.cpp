/* scanTranslationConstraint (libs/matching scan_constraint.h) on scans cast
 * by hand into hand-built rooms, with LMS200-like range noise. */
#include <gtest/gtest.h>
#include <hslam/matching/scan_constraint.h>

#include <cmath>
#include <optional>
#include <random>

using hslam::matching::scanTranslationConstraint;
using mrpt::math::TPoint2D;

namespace
{
constexpr double kDeg = M_PI / 180;

/** Range along a beam from the origin at `bearing` to the line n . p = d
 * (n unit), if it lies ahead within maxRange. */
std::optional<double> rangeToLine(double bearing, const Eigen::Vector2d& n, double d, double maxRange)
{
	const double c = n.x() * std::cos(bearing) + n.y() * std::sin(bearing);
	if (std::abs(c) < 1e-9) return std::nullopt;
	const double r = d / c;
	if (r <= 0 || r > maxRange) return std::nullopt;
	return r;
}

/** An LMS200 (181 beams, 1 deg, facing +x) in a corridor along x of walls
 * y = -1 and y = +1, with an end wall x = endX_m if endX_m > 0; ranges
 * beyond maxRange are no return; 1 cm of range noise. */
std::vector<TPoint2D> corridorScan(double endX_m, double maxRange_m, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> noise(0.0, 0.01);
	std::vector<TPoint2D> out;
	for (int k = -90; k <= 90; ++k)
	{
		const double b = k * kDeg;
		std::optional<double> r;
		for (const auto& [n, d] : {std::pair{Eigen::Vector2d(0, 1), 1.0}, std::pair{Eigen::Vector2d(0, -1), 1.0},
								   std::pair{Eigen::Vector2d(1, 0), endX_m}})
		{
			if (d <= 0) continue;
			const auto ri = rangeToLine(b, n, d, maxRange_m);
			if (ri && (!r || *ri < *r)) r = ri;
		}
		if (!r) continue;
		const double rn = *r + noise(rng);
		out.push_back({rn * std::cos(b), rn * std::sin(b)});
	}
	return out;
}
}  // namespace

TEST(ScanConstraint, ABareCorridorLeavesItsAxisUnconstrained)
{
	// Two walls 1 m either side, the scanner's 8 m reach short of any end:
	// every normal is across the corridor, range noise tilts them by a few
	// degrees at most. Share of the information along the axis: ~0.
	for (unsigned seed = 1; seed <= 5; ++seed)
	{
		const auto c = scanTranslationConstraint(corridorScan(0, 8.0, seed), 0.2, 0.05);
		EXPECT_GT(c.points, 100u);
		EXPECT_LT(c.weakest_fraction, 0.003) << "seed " << seed;  // measured 0.0003-0.0006
		EXPECT_GT(std::abs(c.weakest.x()), 0.99) << "seed " << seed;  // the axis
	}
}

TEST(ScanConstraint, AnEndWallInReachConstrainsTheAxis)
{
	// The same corridor closed 6 m ahead: the end wall's 2 m hold a few
	// percent of the points' weight, well above a bare corridor's share.
	for (unsigned seed = 1; seed <= 5; ++seed)
	{
		const auto c = scanTranslationConstraint(corridorScan(6.0, 8.0, seed), 0.2, 0.05);
		EXPECT_GT(c.weakest_fraction, 0.02) << "seed " << seed;
		EXPECT_LT(c.weakest_fraction, 0.5);
	}
}

TEST(ScanConstraint, ACornerCountsInEveryDirection)
{
	// A right-angled corner: a neighbourhood spanning both walls spreads
	// across by far more than range noise and counts in every direction; the
	// two walls alone constrain both axes equally.
	std::vector<TPoint2D> corner;
	for (int i = 0; i <= 20; ++i) corner.push_back({1.0, -1.0 + 0.05 * i});  // x = 1, y -1 .. 0
	for (int i = 1; i <= 20; ++i) corner.push_back({1.0 - 0.05 * i, 0.0});  // y = 0, x 1 .. 0
	const auto c = scanTranslationConstraint(corner, 0.2, 0);
	EXPECT_EQ(c.points, corner.size());
	EXPECT_NEAR(c.weakest_fraction, 0.5, 0.03);
}

TEST(ScanConstraint, TooFewPointsCountForNothing)
{
	const std::vector<TPoint2D> sparse{{1, 0}, {2, 0}, {3, 0}};  // no 4 within 0.2 m of each other
	const auto c = scanTranslationConstraint(sparse, 0.2, 0.05);
	EXPECT_EQ(c.points, 0u);
	EXPECT_EQ(c.weakest_fraction, 0.0);
}
