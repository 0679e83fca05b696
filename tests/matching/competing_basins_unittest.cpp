/* widenForCompetingBasins (competing_basins.h) on hand-derived cases. The
 * chosen result sits at (0, 0, 0) with standard deviations 0.05 m, 0.05 m,
 * 1 deg; a competitor at (0.5, 0, 0) is 10 standard deviations away
 * (chi^2 = 100 > 16.27), so when it fits at least 0.75 of the chosen fit its
 * offset is added: xx = 0.05^2 + 0.5^2 = 0.2525 m^2, the other entries
 * unchanged. A heading competitor 40 deg away adds (40 deg)^2 to the yaw
 * variance, wrapped across +-180 deg. */
#include <gtest/gtest.h>
#include <hslam/matching/competing_basins.h>

#include <cmath>

using namespace hslam::matching;
using mrpt::poses::CPose2D;

namespace
{
const double kDeg = M_PI / 180.0;

TPoseMatch result(const CPose2D& pose, double fit)
{
	TPoseMatch m;
	m.pose = pose;
	m.fit = fit;
	m.quality = EMatchQuality::good;
	m.covariance = Eigen::Vector3d(0.05 * 0.05, 0.05 * 0.05, kDeg * kDeg).asDiagonal();
	return m;
}
}  // namespace

TEST(CompetingBasins, AFarResultFittingNearlyAsWellWidensTheCovarianceByItsOffset)
{
	TPoseMatch chosen = result(CPose2D(0, 0, 0), 0.70);
	EXPECT_TRUE(widenForCompetingBasins(chosen, {chosen, result(CPose2D(0.5, 0, 0), 0.60)}, {}));
	EXPECT_NEAR(chosen.covariance(0, 0), 0.2525, 1e-12);
	EXPECT_NEAR(chosen.covariance(1, 1), 0.0025, 1e-12);
	EXPECT_NEAR(chosen.covariance(2, 2), kDeg * kDeg, 1e-12);
	EXPECT_NEAR(chosen.covariance(0, 1), 0.0, 1e-12);
	// the basin's own covariance is kept (the motion prior judges by it)
	ASSERT_TRUE(chosen.basin_covariance.has_value());
	EXPECT_NEAR((*chosen.basin_covariance)(0, 0), 0.0025, 1e-12);
}

TEST(CompetingBasins, AResultFittingClearlyWorseDoesNotCompete)
{
	TPoseMatch chosen = result(CPose2D(0, 0, 0), 0.70);
	// 0.50 / 0.70 = 0.71 < 0.75
	EXPECT_FALSE(widenForCompetingBasins(chosen, {result(CPose2D(0.5, 0, 0), 0.50)}, {}));
	EXPECT_NEAR(chosen.covariance(0, 0), 0.0025, 1e-12);
	EXPECT_FALSE(chosen.basin_covariance.has_value());
}

TEST(CompetingBasins, TheSameBasinAndFailedResultsDoNotCompete)
{
	TPoseMatch chosen = result(CPose2D(0, 0, 0), 0.70);
	// 0.15 m = 3 sigma: chi^2 = 9 < 16.27, the same basin.
	TPoseMatch failed = result(CPose2D(2.0, 0, 0), 0.69);
	failed.quality = EMatchQuality::failed;
	EXPECT_FALSE(widenForCompetingBasins(chosen, {result(CPose2D(0.15, 0, 0), 0.70), failed}, {}));
	EXPECT_NEAR(chosen.covariance(0, 0), 0.0025, 1e-12);
}

TEST(CompetingBasins, TheFarthestCompetitorIsAddedWithItsHeadingWrapped)
{
	TPoseMatch chosen = result(CPose2D(0, 0, 170 * kDeg), 0.40);
	const TPoseMatch nearer = result(CPose2D(0, 0, 160 * kDeg), 0.39);  // 10 deg
	const TPoseMatch farther = result(CPose2D(0, 0, -150 * kDeg), 0.33);  // 40 deg across +-180
	EXPECT_TRUE(widenForCompetingBasins(chosen, {nearer, farther}, {}));
	EXPECT_NEAR(chosen.covariance(2, 2), kDeg * kDeg + std::pow(40 * kDeg, 2), 1e-9);
	EXPECT_NEAR(chosen.covariance(0, 0), 0.0025, 1e-12);
}

TEST(CompetingBasins, ARatioOfZeroTurnsItOff)
{
	TPoseMatch chosen = result(CPose2D(0, 0, 0), 0.70);
	TCompetingBasinOptions off;
	off.fit_ratio = 0;
	EXPECT_FALSE(widenForCompetingBasins(chosen, {result(CPose2D(0.5, 0, 0), 0.70)}, off));
	EXPECT_NEAR(chosen.covariance(0, 0), 0.0025, 1e-12);
}
