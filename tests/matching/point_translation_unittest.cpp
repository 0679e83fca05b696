/* estimatePointTranslation (thesis 4.4.2 iii "method 1"): hand-made point
 * sets whose translation is known exactly. */
#include <gtest/gtest.h>
#include <hslam/matching/point_translation.h>
#include <hslam/matching/scan_points.h>

#include <cmath>

using namespace hslam::matching;
using mrpt::math::TPoint2D;

namespace
{
/** A 5 x 4 grid with 1 m spacing: every point's nearest neighbour is unique
 * for shifts under 0.5 m. */
std::vector<TPoint2D> grid()
{
	std::vector<TPoint2D> points;
	for (int i = 0; i < 5; ++i)
		for (int j = 0; j < 4; ++j) points.push_back({1.0 * i, 1.0 * j});
	return points;
}

/** current = R(-phi) (previous - t): then R(phi) current + t = previous. */
std::vector<TPoint2D> moved(const std::vector<TPoint2D>& previous, double phi, double tx, double ty)
{
	std::vector<TPoint2D> out;
	const double c = std::cos(phi), s = std::sin(phi);
	for (const auto& p : previous)
	{
		const double x = p.x - tx, y = p.y - ty;
		out.push_back({c * x + s * y, -s * x + c * y});
	}
	return out;
}
}  // namespace

TEST(PointTranslation, RecoversAPureShiftInOneStep)
{
	const auto previous = grid();
	const auto map = toPointsMap(previous);
	const auto r = estimatePointTranslation(map, moved(previous, 0.0, 0.1, 0.05), 0.0, Eigen::Vector2d::Zero(), 0.5,
											0.2, 3);
	// Every point has the same residual (0.1, 0.05): the weighted mean is exact.
	EXPECT_NEAR(r.translation_m.x(), 0.1, 1e-5);
	EXPECT_NEAR(r.translation_m.y(), 0.05, 1e-5);
	EXPECT_EQ(r.inliers, previous.size());
	EXPECT_NEAR(r.rms_m, 0.0, 1e-5);
	// Zero residual: the covariance is the 5 cm floor, not zero.
	EXPECT_NEAR(r.covariance(0, 0), 0.05 * 0.05, 1e-12);
	EXPECT_NEAR(r.covariance(1, 1), 0.05 * 0.05, 1e-12);
	EXPECT_DOUBLE_EQ(r.covariance(0, 1), 0.0);
}

TEST(PointTranslation, CorridorAxisIsLeftUnconstrained)
{
	// Two parallel walls 2 m apart along x, 2 cm point spacing: a shift along
	// the walls is not observable; across them it is.
	std::vector<TPoint2D> previous;
	for (int i = 0; i < 200; ++i) previous.push_back({0.02 * i, -1.0}), previous.push_back({0.02 * i, 1.0});
	const auto r = estimatePointTranslation(toPointsMap(previous), moved(previous, 0.0, 0.0, 0.05), 0.0,
											Eigen::Vector2d::Zero(), 0.5, 0.2, 3);
	EXPECT_NEAR(r.translation_m.y(), 0.05, 1e-3);
	EXPECT_GT(r.covariance(0, 0), 100.0);  // along the axis: the geometric cap (100 m std)
	EXPECT_NEAR(r.covariance(1, 1), 0.05 * 0.05, 1e-6);  // across: the 5 cm floor
}

TEST(PointTranslation, UsesTheGivenRotation)
{
	const auto previous = grid();
	const double phi = 10 * M_PI / 180;
	const auto r = estimatePointTranslation(toPointsMap(previous), moved(previous, phi, -0.2, 0.15), phi,
											Eigen::Vector2d::Zero(), 0.5, 0.2, 3);
	EXPECT_NEAR(r.translation_m.x(), -0.2, 1e-5);
	EXPECT_NEAR(r.translation_m.y(), 0.15, 1e-5);
}

TEST(PointTranslation, PointsOutsideTheGateAreNotInliers)
{
	const auto previous = grid();
	auto current = moved(previous, 0.0, 0.1, 0.0);
	current.push_back({20.0, 20.0});  // 16 m from the nearest grid point
	const auto r = estimatePointTranslation(toPointsMap(previous), current, 0.0, Eigen::Vector2d::Zero(), 0.5, 0.2, 2);
	EXPECT_EQ(r.inliers, previous.size());
	EXPECT_NEAR(r.translation_m.x(), 0.1, 1e-5);
}

TEST(PointTranslation, EmptyInputKeepsTheInitialTranslation)
{
	const Eigen::Vector2d initial(0.3, -0.4);
	const auto r = estimatePointTranslation(toPointsMap({}), grid(), 0.0, initial, 0.5, 0.2, 3);
	EXPECT_EQ(r.translation_m, initial);
	EXPECT_EQ(r.inliers, 0u);
}
