/* adaptiveVoxelFilter, closureInformationGain (hand-derived cases) and the
 * correlative matcher's thinned search against its full search. */
#include <gtest/gtest.h>
#include <hslam/graph/CCorrelativeScanMatcher.h>
#include <hslam/graph/CLoopClosureDetector.h>
#include <hslam/graph/adaptive_voxel_filter.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

#include "sim_scans.h"

using namespace hslam::graph;
using mrpt::math::TPoint2Df;

namespace
{
/** 1000 points 1 cm apart along x from 0 to 9.99 m. */
std::vector<TPoint2Df> denseLine()
{
	std::vector<TPoint2Df> pts;
	for (int i = 0; i < 1000; ++i) pts.push_back({0.01f * i, 0.2f});
	return pts;
}
}  // namespace

TEST(AdaptiveVoxelFilter, VoxelFilterKeepsTheFirstPointOfEachCell)
{
	const auto kept = voxelFilter(denseLine(), 0.1);
	ASSERT_EQ(kept.size(), 100u);  // cells [0, 0.1), ..., [9.9, 10)
	for (size_t k = 0; k < kept.size(); ++k) EXPECT_NEAR(kept[k].x, 0.1 * k, 0.011);
}

TEST(AdaptiveVoxelFilter, CoarsestCellThatKeepsTheMinimum)
{
	// 9.99 m of line: a cell c keeps ceil(9.99 / c) points; the largest cell
	// keeping 100 is 0.0999 m, found to within 10 % -> 100..110 points
	const auto kept = adaptiveVoxelFilter(denseLine(), 100, 0.9);
	EXPECT_GE(kept.size(), 100u);
	EXPECT_LE(kept.size(), 110u);
	// the maximum cell already keeps enough: taken as it is
	EXPECT_EQ(adaptiveVoxelFilter(denseLine(), 10, 0.9).size(), 12u);
}

TEST(AdaptiveVoxelFilter, FewPointsOrZeroMinimumAreKeptWhole)
{
	const auto line = denseLine();
	EXPECT_EQ(adaptiveVoxelFilter(line, 1000, 0.9).size(), 1000u);
	EXPECT_EQ(adaptiveVoxelFilter(line, 5000, 0.9).size(), 1000u);
	EXPECT_EQ(adaptiveVoxelFilter(line, 0, 0.9).size(), 1000u);
}

TEST(ClosureInformationGain, HandDerivedValues)
{
	const double sxy = 0.05, syaw = mrpt::DEG2RAD(1.0);
	const Eigen::Vector3d closureVar(sxy * sxy, sxy * sxy, syaw * syaw);
	// the graph knows the relative pose as well as a closure would:
	// det(2 C) / det(C) = 8 -> 0.5 ln 8
	EXPECT_NEAR(closureInformationGain(closureVar.asDiagonal(), sxy, syaw), 0.5 * std::log(8.0), 1e-12);
	// the graph already knows the relative pose exactly: nothing to learn
	EXPECT_NEAR(closureInformationGain(Eigen::Matrix3d::Zero(), sxy, syaw), 0.0, 1e-12);
	// 3x the closure's variance in x and y only: 0.5 ln(4 * 4 * 1) = ln 4
	const Eigen::Vector3d xyOnly(3 * sxy * sxy, 3 * sxy * sxy, 0);
	EXPECT_NEAR(closureInformationGain(xyOnly.asDiagonal(), sxy, syaw), std::log(4.0), 1e-12);
	// a rotated (correlated) covariance has the same determinant: same gain
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	R.topLeftCorner<2, 2>() << std::cos(0.7), -std::sin(0.7), std::sin(0.7), std::cos(0.7);
	const Eigen::Vector3d aniso(0.04, 0.0025, 0.0003);
	const Eigen::Matrix3d rotated = R * Eigen::Matrix3d(aniso.asDiagonal()) * R.transpose();
	const double expected = 0.5 * std::log((0.04 + sxy * sxy) * (0.0025 + sxy * sxy) * (0.0003 + syaw * syaw) /
										   closureVar.prod());
	EXPECT_NEAR(closureInformationGain(rotated, sxy, syaw), expected, 1e-9);
}

TEST(CorrelativeScanMatcher, ThinnedSearchFindsThePoseOfTheFullSearch)
{
	using namespace hslam::graph::testing;
	std::mt19937_64 rng(11);
	const auto world = irregularRoom();
	const mrpt::math::TPose2D frame{3.0, 3.5, 0.0}, robot{4.0, 4.1, 0.4};
	const auto reference = scanPoints(world, frame, rng);
	const auto query = scanPoints(world, robot, rng);
	const auto truth = relativePose(frame, robot);
	const mrpt::math::TPose2D guess{truth.x + 0.5, truth.y - 0.3, truth.phi - mrpt::DEG2RAD(12.0)};
	TCorrelativeMatcherOptions full, thinned;
	full.search_min_points = 0;
	thinned.search_min_points = 60;
	CCorrelativeScanMatcher a(full), b(thinned);
	a.setReference(reference), b.setReference(reference);
	const auto ma = a.match(query, guess), mb = b.match(query, guess);
	ASSERT_TRUE(ma.found && mb.found);
	EXPECT_EQ(ma.search_points, ma.query_points);
	EXPECT_GE(mb.search_points, 60u);
	EXPECT_LT(mb.search_points, mb.query_points * 3 / 4);
	EXPECT_NEAR(mb.pose.x, ma.pose.x, 0.01);
	EXPECT_NEAR(mb.pose.y, ma.pose.y, 0.01);
	EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(mb.pose.phi - ma.pose.phi)), 0.0, 0.2);
	EXPECT_NEAR(mb.score, ma.score, 0.01);  // both scored with every point
	EXPECT_NEAR(mb.pose.x, truth.x, 0.03);
}
