/* CGapSearch: the wide search for the first match after an odometry gap of
 * unknown motion (issue 12, "Recovery"). Hand-made cases: an L-shaped room
 * seen from two poses 1.2 m and 36 deg apart (csail cut at entry 500 starts
 * with such a step), and the window rule. */
#include <hslam/benchdata/synthetic_scan.h>
#include <hslam/slam/CGapSearch.h>

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

using namespace hslam;

namespace
{
/** An L-shaped room (no symmetry) with a pillar, 10 x 8 m. */
std::vector<benchdata::TWall> lRoom()
{
	const std::vector<mrpt::math::TPoint2D> c{{0, 0}, {10, 0}, {10, 4}, {6, 4}, {6, 8}, {0, 8}};
	std::vector<benchdata::TWall> walls;
	for (size_t i = 0; i < c.size(); ++i) walls.push_back({c[i], c[(i + 1) % c.size()], 0.01});
	walls.push_back({{3, 3}, {3.4, 3}, 0.01});
	walls.push_back({{3.4, 3}, {3.4, 3.4}, 0.01});
	walls.push_back({{3.4, 3.4}, {3, 3.4}, 0.01});
	walls.push_back({{3, 3.4}, {3, 3}, 0.01});
	return walls;
}

/** The scan's valid returns in the robot frame. */
mrpt::maps::CSimplePointsMap scanFrom(const mrpt::poses::CPose2D& pose, uint32_t seed)
{
	benchdata::TScanLayout layout;
	layout.beams = 361;
	layout.max_range_m = 30;
	const auto sim = benchdata::simulateScan(lRoom(), pose, layout, seed);
	mrpt::maps::CSimplePointsMap points;
	points.insertObservation(sim.scan);
	return points;
}
}  // namespace

TEST(GapSearch, FindsAStepOfUnknownMotionFarOutsideIcpsBasin)
{
	const mrpt::poses::CPose2D first(2, 1.5, mrpt::DEG2RAD(40)), second(2.9, 2.3, mrpt::DEG2RAD(76));
	const mrpt::poses::CPose2D truth = second - first;  // 1.20 m, 36 deg
	ASSERT_NEAR(truth.norm(), 1.2, 0.01);
	slam::CGapSearch search;
	const auto window = search.windowFor(Eigen::Vector3d(0.36, 0.36, std::pow(mrpt::DEG2RAD(35.0), 2)).asDiagonal());
	ASSERT_TRUE(window.has_value());
	EXPECT_DOUBLE_EQ(window->xy_m, 1.8);  // 3 sigma of 0.6 m
	EXPECT_DOUBLE_EQ(window->yaw_rad, mrpt::DEG2RAD(60.0));  // 3 x 35 deg, capped
	// the prediction is "no motion", as at the start of a log
	const auto found = search.search(scanFrom(first, 1), scanFrom(second, 2), mrpt::poses::CPose2D(), *window);
	ASSERT_TRUE(found.has_value());
	EXPECT_LT(found->distanceTo(truth), 0.1) << found->asString();
	EXPECT_LT(std::abs(mrpt::math::wrapToPi(found->phi() - truth.phi())), mrpt::DEG2RAD(2.0));
}

TEST(GapSearch, NoSearchWhereIcpsBasinCoversTheWindowOrWhenOff)
{
	slam::CGapSearch search;
	// a constant-velocity prior over 0.1 s: 0.15 m, 8 deg -> within 0.5 m and 15 deg at 3 sigma
	const Eigen::Matrix3d small = Eigen::Vector3d(0.0225, 0.0225, std::pow(mrpt::DEG2RAD(8.0) / 3.0, 2)).asDiagonal();
	EXPECT_FALSE(search.windowFor(small).has_value());
	// a wide rotation alone is enough to search
	const Eigen::Matrix3d turn = Eigen::Vector3d(0.0225, 0.0225, std::pow(mrpt::DEG2RAD(10.0), 2)).asDiagonal();
	ASSERT_TRUE(search.windowFor(turn).has_value());
	EXPECT_NEAR(search.windowFor(turn)->yaw_rad, mrpt::DEG2RAD(30.0), 1e-12);
	slam::TGapSearchOptions off;
	off.enabled = false;
	EXPECT_FALSE(slam::CGapSearch(off).windowFor(turn).has_value());
}

TEST(GapSearch, PointsBeyondItsRangeAreLeftOut)
{
	const graph::TSearchWindow window{1.0, mrpt::DEG2RAD(30.0)};
	mrpt::maps::CSimplePointsMap far;  // a wall 25 m ahead, seen from two poses 0.5 m apart
	mrpt::maps::CSimplePointsMap nearer;
	for (int i = 0; i < 50; ++i)
	{
		far.insertPoint(25.0f, -2.5f + 0.1f * static_cast<float>(i));
		nearer.insertPoint(24.5f, -2.5f + 0.1f * static_cast<float>(i));
	}
	// beyond max_range_m (20 m) nothing is left to search with
	EXPECT_FALSE(slam::CGapSearch().search(far, nearer, mrpt::poses::CPose2D(), window).has_value());
	slam::TGapSearchOptions longer;
	longer.max_range_m = 30;
	const auto found = slam::CGapSearch(longer).search(far, nearer, mrpt::poses::CPose2D(), window);
	ASSERT_TRUE(found.has_value());
	EXPECT_NEAR(found->x(), 0.5, 0.1);  // the robot moved 0.5 m towards the wall
}

TEST(GapSearch, AfterAPoorMatchWithOdometryTheHeadingWindowIsWide)
{
	// odometry's model for a 1 m step turning 12 deg: 0.12 m and 5 deg std,
	// a window that ICP's restarts cover; a slip of 40 deg is outside it
	slam::CGapSearch search;
	const Eigen::Matrix3d model = Eigen::Vector3d(0.0144, 0.0144, std::pow(mrpt::DEG2RAD(5.0), 2)).asDiagonal();
	EXPECT_FALSE(search.windowFor(model).has_value());
	const auto window = search.slipWindowFor(model);
	ASSERT_TRUE(window.has_value());
	EXPECT_NEAR(window->xy_m, 0.36, 1e-12);  // 3 sigma
	EXPECT_NEAR(window->yaw_rad, mrpt::DEG2RAD(45.0), 1e-12);  // slip_min_yaw_deg
	// the room seen from two poses: odometry said 12 deg, the robot turned 52
	const mrpt::poses::CPose2D first(2, 1.5, mrpt::DEG2RAD(40)), second(2.9, 2.0, mrpt::DEG2RAD(92));
	const mrpt::poses::CPose2D truth = second - first;
	const mrpt::poses::CPose2D odometry(truth.x(), truth.y(), truth.phi() - mrpt::DEG2RAD(40.0));
	const auto found = search.search(scanFrom(first, 3), scanFrom(second, 4), odometry, *window,
									   slam::ESearchKind::after_poor_match);
	ASSERT_TRUE(found.has_value());
	EXPECT_LT(found->distanceTo(truth), 0.15) << found->asString();
	EXPECT_LT(std::abs(mrpt::math::wrapToPi(found->phi() - truth.phi())), mrpt::DEG2RAD(2.0));
	slam::TGapSearchOptions off;
	off.after_poor_match = false;
	EXPECT_FALSE(slam::CGapSearch(off).slipWindowFor(model).has_value());
}

TEST(GapSearch, APriorThatHoldsNoHeadingIsSearchedRoundTheWholeCircle)
{
	// A turn rate carried 8 s without odometry (intel laser only, t = 947 s):
	// heading std 245 deg, the robot 140 deg from the prediction. 3 x 60 deg
	// reaches 180: the whole circle; 3 x 50 deg does not: capped at 60.
	slam::CGapSearch search;
	const auto cov = [](double yawStd_deg)
	{ return Eigen::Matrix3d(Eigen::Vector3d(1.0, 1.0, std::pow(mrpt::DEG2RAD(yawStd_deg), 2)).asDiagonal()); };
	EXPECT_NEAR(search.windowFor(cov(50.0))->yaw_rad, mrpt::DEG2RAD(60.0), 1e-12);
	EXPECT_NEAR(search.windowFor(cov(60.0))->yaw_rad, M_PI, 1e-12);
	const auto window = search.windowFor(cov(245.0));
	ASSERT_TRUE(window.has_value());
	EXPECT_NEAR(window->yaw_rad, M_PI, 1e-12);
	const mrpt::poses::CPose2D first(2, 1.5, mrpt::DEG2RAD(40)), second(2.3, 1.7, mrpt::DEG2RAD(70));
	const mrpt::poses::CPose2D truth = second - first;
	const mrpt::poses::CPose2D predicted(truth.x(), truth.y(), truth.phi() + mrpt::DEG2RAD(140.0));
	const auto found = search.search(scanFrom(first, 5), scanFrom(second, 6), predicted, *window);
	ASSERT_TRUE(found.has_value());
	EXPECT_LT(found->distanceTo(truth), 0.15) << found->asString();
	EXPECT_LT(std::abs(mrpt::math::wrapToPi(found->phi() - truth.phi())), mrpt::DEG2RAD(2.0));
	slam::TGapSearchOptions off;
	off.whole_circle_if_heading_unknown = false;
	EXPECT_NEAR(slam::CGapSearch(off).windowFor(cov(245.0))->yaw_rad, mrpt::DEG2RAD(60.0), 1e-12);
	const auto capped = slam::CGapSearch(off).search(scanFrom(first, 5), scanFrom(second, 6), predicted,
													 *slam::CGapSearch(off).windowFor(cov(245.0)));
	EXPECT_TRUE(!capped || std::abs(mrpt::math::wrapToPi(capped->phi() - truth.phi())) > mrpt::DEG2RAD(30.0));
}
