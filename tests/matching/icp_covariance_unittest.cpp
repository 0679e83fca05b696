/* geometricAlignmentCovariance (icp_covariance.h) on walls whose information
 * matrix is worked out by hand. Two straight walls far apart, points every
 * 0.1 m, so every point's six nearest reference points lie on its own wall
 * and its normal is exactly the wall's:
 *   wall A: y = 2, x = -1.0 ... 1.0  (21 points, normal (0, +-1))
 *   wall B: x = 3, y = -1.0 ... 1.0  (21 points, normal (+-1, 0))
 * A point p (lever arm a = R p) adds J J' with J = (n_x, n_y, n_y a_x - n_x a_y):
 * wall A adds (0, 1, x) (x), wall B (1, 0, -y) (x). With sum x = 0 and
 * sum x^2 = 0.01 * 2 * (1 + 4 + ... + 100) = 7.7:
 *   H = diag(21, 21, 7.7 + 7.7).
 * Without residual the variance is sigma^2 = min_sigma^2 * correlation_factor
 * = 0.02^2 * 10 = 0.004, and cov = sigma^2 H^-1. (The corridor case, an axis
 * with no information, is in icp_unittest.cpp.) */
#include <gtest/gtest.h>
#include <hslam/matching/icp_covariance.h>
#include <hslam/matching/scan_points.h>

#include <cmath>

using namespace hslam::matching;
using mrpt::math::TPoint2D;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kSigma2 = 0.02 * 0.02 * 10;  // default min_sigma_m, correlation_factor
constexpr double kCap2 = 100.0 * 100.0;  // default max_std_m, squared

/** y = yWall for x = -1 ... 1 every 0.1 m (21 points). */
std::vector<TPoint2D> wallA(double yWall = 2.0)
{
	std::vector<TPoint2D> p;
	for (int i = -10; i <= 10; ++i) p.push_back({0.1 * i, yWall});
	return p;
}

/** x = 3 for y = -halfCount ... halfCount times 0.1 m. */
std::vector<TPoint2D> wallB(int halfCount = 10, double step_m = 0.1)
{
	std::vector<TPoint2D> p;
	for (int j = -halfCount; j <= halfCount; ++j) p.push_back({3.0, step_m * j});
	return p;
}

std::vector<TPoint2D> both(std::vector<TPoint2D> a, const std::vector<TPoint2D>& b)
{
	a.insert(a.end(), b.begin(), b.end());
	return a;
}

/** |actual - expected| within `relative` of expected. */
void expectRelative(double actual, double expected, double relative = 1e-5)
{
	EXPECT_NEAR(actual, expected, relative * std::abs(expected));
}
}  // namespace

TEST(IcpCovarianceByHand, TwoPerpendicularWallsGiveTheInverseInformation)
{
	const auto map = toPointsMap(both(wallA(), wallB()));
	size_t matched = 0;
	const Eigen::Matrix3d cov = geometricAlignmentCovariance(map, map, CPose2D(), TGeometricCovarianceOptions(), &matched);
	EXPECT_EQ(matched, 42u);
	expectRelative(cov(0, 0), kSigma2 / 21);  // 1.905e-4 m^2: wall B's 21 points along x
	expectRelative(cov(1, 1), kSigma2 / 21);  // wall A's along y
	expectRelative(cov(2, 2), kSigma2 / 15.4);  // 2.597e-4 rad^2: both lever arms
	EXPECT_NEAR(cov(0, 1), 0.0, 1e-12);
	EXPECT_NEAR(cov(0, 2), 0.0, 1e-12);
	EXPECT_NEAR(cov(1, 2), 0.0, 1e-12);
}

TEST(IcpCovarianceByHand, DenselySampledWallCountsPerSpacingNotPerBeam)
{
	// The current scan sees wall A every 0.025 m (81 points), wall B every
	// 0.1 m. Counting every point fully, wall A gives H_yy = 81. With
	// covariance_full_weight_spacing_m = 0.1 each point of wall A counts
	// 0.025 / 0.1 = 0.25: H_yy = 20.25, H_thetatheta = 0.25 * 0.025^2 *
	// sum_{i=-40..40} i^2 (= 44 280) + 7.7 (wall B) = 14.61875; wall B's points
	// (0.1 m apart, the first 3.6 m from wall A's last) count fully: H_xx = 21.
	std::vector<TPoint2D> denseA;
	for (int i = -40; i <= 40; ++i) denseA.push_back({0.025 * i, 2.0});
	const auto reference = toPointsMap(both(wallA(), wallB()));
	const auto current = toPointsMap(both(denseA, wallB()));
	TGeometricCovarianceOptions o;
	size_t matched = 0;
	const Eigen::Matrix3d everyBeam = geometricAlignmentCovariance(reference, current, CPose2D(), o, &matched);
	EXPECT_EQ(matched, 102u);
	expectRelative(everyBeam(1, 1), kSigma2 / 81);
	o.full_weight_spacing_m = 0.1;
	const Eigen::Matrix3d perSpacing = geometricAlignmentCovariance(reference, current, CPose2D(), o, &matched);
	EXPECT_EQ(matched, 102u);
	expectRelative(perSpacing(0, 0), kSigma2 / 21);
	expectRelative(perSpacing(1, 1), kSigma2 / 20.25);
	expectRelative(perSpacing(2, 2), kSigma2 / 14.61875);
}

TEST(IcpCovarianceByHand, PointsAllOnTopOfEachOtherGiveTheCapNotNaN)
{
	// Twelve returns of one spot: every spacing weight is 0, nothing is known.
	const auto reference = toPointsMap(both(wallA(), wallB()));
	const auto current = toPointsMap(std::vector<TPoint2D>(12, TPoint2D{0.0, 2.0}));
	TGeometricCovarianceOptions o;
	o.full_weight_spacing_m = 0.05;
	size_t matched = 0;
	const Eigen::Matrix3d cov = geometricAlignmentCovariance(reference, current, CPose2D(), o, &matched);
	EXPECT_EQ(matched, 12u);
	EXPECT_TRUE(cov.isApprox(Eigen::Matrix3d::Identity() * kCap2));
}

TEST(IcpCovarianceByHand, LeverArmCouplesTranslationAndRotation)
{
	// The current scan taken 0.5 m further along x: the pose (0.5, 0, 0) puts
	// its points on the walls, and the lever arms are measured from there.
	// Wall A: a = (x - 0.5, 2), J = (0, 1, x - 0.5): H_yy = 21,
	// H_ytheta = sum (x - 0.5) = -10.5, sum (x - 0.5)^2 = 7.7 + 21 * 0.25 = 12.95.
	// Wall B: a = (2.5, y), J = (1, 0, -y) as before.
	// H = [21 0 0; 0 21 -10.5; 0 -10.5 20.65]; the (y, theta) block has
	// determinant 21 * 20.65 - 10.5^2 = 323.4.
	const auto reference = toPointsMap(both(wallA(), wallB()));
	std::vector<TPoint2D> current;
	for (const auto& p : both(wallA(), wallB())) current.push_back({p.x - 0.5, p.y});
	const Eigen::Matrix3d cov =
		geometricAlignmentCovariance(reference, current, CPose2D(0.5, 0, 0), TGeometricCovarianceOptions());
	expectRelative(cov(0, 0), kSigma2 / 21);
	expectRelative(cov(1, 1), kSigma2 * 20.65 / 323.4);
	expectRelative(cov(2, 2), kSigma2 * 21 / 323.4);
	expectRelative(cov(1, 2), kSigma2 * 10.5 / 323.4);  // y error and heading error go together
	EXPECT_NEAR(cov(0, 2), 0.0, 1e-12);
}

TEST(IcpCovarianceByHand, ResidualSetsTheVarianceAboveItsFloor)
{
	// Wall A alone, seen 5 cm off its reference (y = 2.05): every point is
	// 0.05 m from its nearest reference point along the normal, so
	// sigma^2 = 0.05^2 * 10 = 0.025 (above the floor 0.004). Nothing
	// constrains x: its variance is the cap. H = [0 0 0; 0 21 0; 0 0 7.7].
	const auto reference = toPointsMap(wallA(2.0));
	size_t matched = 0;
	const Eigen::Matrix3d cov = geometricAlignmentCovariance(reference, toPointsMap(wallA(2.05)), CPose2D(),
															 TGeometricCovarianceOptions(), &matched);
	EXPECT_EQ(matched, 21u);
	const double sigma2 = 0.05 * 0.05 * 10;
	expectRelative(cov(0, 0), kCap2, 1e-9);
	expectRelative(cov(1, 1), sigma2 / 21, 1e-4);  // float storage of 2.05
	expectRelative(cov(2, 2), sigma2 / 7.7, 1e-4);
}

TEST(IcpCovarianceByHand, ShortCrossWallCountsOnlyAboveTheDegenerateFraction)
{
	// Wall B shortened to 7 points (y = -0.15 ... 0.15 every 5 cm): 28 matched
	// points, of which 7 constrain x (translation information diag(7, 21)).
	// degenerate_min_fraction 0.2: 7 >= 0.2 * 28 = 5.6, x keeps sigma^2 / 7;
	// 0.3: 7 < 8.4, x is unconstrained and gets the cap on top.
	const auto map = toPointsMap(both(wallA(), wallB(3, 0.05)));
	TGeometricCovarianceOptions o;
	o.degenerate_min_fraction = 0.2;
	size_t matched = 0;
	const Eigen::Matrix3d kept = geometricAlignmentCovariance(map, map, CPose2D(), o, &matched);
	EXPECT_EQ(matched, 28u);
	expectRelative(kept(0, 0), kSigma2 / 7);
	expectRelative(kept(1, 1), kSigma2 / 21);
	o.degenerate_min_fraction = 0.3;
	const Eigen::Matrix3d capped = geometricAlignmentCovariance(map, map, CPose2D(), o);
	expectRelative(capped(0, 0), kCap2 + kSigma2 / 7, 1e-9);
	expectRelative(capped(1, 1), kSigma2 / 21);  // y is constrained by 21 of 28: untouched
}
