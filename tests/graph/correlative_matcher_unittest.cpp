/* CCorrelativeScanMatcher against simulated scans with exact ground truth. */
#include <gtest/gtest.h>
#include <hslam/graph/CCorrelativeScanMatcher.h>
#include <hslam/graph/CPoseGraph.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/LU>

#include "sim_scans.h"

using namespace hslam::graph;
using namespace hslam::graph::testing;
using mrpt::math::TPose2D;

namespace
{
/** Reference: three scans of the irregular room in the frame of the first. */
TPointCloud2D roomReference(const hslam::sim::CWorld& world, std::mt19937_64& rng)
{
	const TPose2D frame{3.0, 3.5, 0.0};
	TPointCloud2D ref;
	for (const TPose2D& p : {frame, TPose2D{5.0, 3.0, 1.2}, TPose2D{7.0, 2.5, 2.8}})
	{
		const auto pts = transformPoints(scanPoints(world, p, rng), p, frame);
		ref.insert(ref.end(), pts.begin(), pts.end());
	}
	return ref;
}

/** A room mirrored by a half turn: the query (a scan at the origin) fits at
 * its pose and rotated by 180 deg. */
std::pair<CCorrelativeScanMatcher, TPointCloud2D> mirroredRoom()
{
	std::mt19937_64 rng(9);
	hslam::sim::CWorld w;
	addBox(w, -4, -2, 4, 2);
	CCorrelativeScanMatcher matcher;
	const TPose2D robot{0, 0, 0};
	auto reference = scanPoints(w, robot, rng);
	const auto back = transformPoints(scanPoints(w, {0, 0, M_PI}, rng), {0, 0, M_PI});
	reference.insert(reference.end(), back.begin(), back.end());
	matcher.setReference(reference);
	return {std::move(matcher), scanPoints(w, robot, rng)};
}
}  // namespace

TEST(CorrelativeScanMatcher, RecoversKnownOffsetOf80cmAnd20deg)
{
	std::mt19937_64 rng(7);
	const auto world = irregularRoom();
	TCorrelativeMatcherOptions opt;
	opt.window_xy_m = 1.2;
	opt.window_yaw_rad = mrpt::DEG2RAD(30.0);
	CCorrelativeScanMatcher matcher(opt);
	matcher.setReference(roomReference(world, rng));
	const TPose2D frame{3.0, 3.5, 0.0}, robot{4.2, 4.4, 0.6};
	const TPose2D truth = relativePose(frame, robot);
	const TPose2D guess{truth.x + 0.8 * std::cos(0.3), truth.y - 0.8 * std::sin(0.3), truth.phi + mrpt::DEG2RAD(20.0)};
	const auto m = matcher.match(scanPoints(world, robot, rng), guess);
	ASSERT_TRUE(m.found);
	EXPECT_NEAR(m.pose.x, truth.x, 0.02);
	EXPECT_NEAR(m.pose.y, truth.y, 0.02);
	EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(m.pose.phi - truth.phi)), 0.0, 0.5);
	EXPECT_GT(m.score, 0.6);
	EXPECT_GT(m.hit_fraction, 0.8);
	// the score surface's covariance is small for a well-constrained room
	EXPECT_LT(std::sqrt(m.covariance(0, 0)), 0.05);
	EXPECT_LT(std::sqrt(m.covariance(2, 2)), mrpt::DEG2RAD(1.0));
	// branch-and-bound scored a small part of the window's leaves
	const double leaves = m.rotations * std::pow(2 * std::ceil(opt.window_xy_m / opt.resolution_m) + 1, 2);
	EXPECT_LT(m.nodes_scored, 0.02 * leaves);
}

TEST(CorrelativeScanMatcher, MatchNearRefinesAGuessWithinACellAndFindsNothingElsewhere)
{
	// matchNear (a closure tracked from the keyframe before): a search of
	// two cells and two rotation steps from a guess a cell and an angle step off.
	std::mt19937_64 rng(7);
	const auto world = irregularRoom();
	CCorrelativeScanMatcher matcher;
	matcher.setReference(roomReference(world, rng));
	const TPose2D frame{3.0, 3.5, 0.0}, robot{4.2, 4.4, 0.6};
	const TPose2D truth = relativePose(frame, robot);
	const auto scan = scanPoints(world, robot, rng);
	const auto searched = matcher.match(scan, {truth.x + 0.3, truth.y - 0.2, truth.phi + 0.1});
	const auto near = matcher.matchNear(scan, {truth.x + 0.04, truth.y - 0.03, truth.phi + mrpt::DEG2RAD(0.6)}, 0.55);
	ASSERT_TRUE(near.found);
	EXPECT_NEAR(near.pose.x, truth.x, 0.02);
	EXPECT_NEAR(near.pose.y, truth.y, 0.02);
	EXPECT_NEAR(mrpt::RAD2DEG(mrpt::math::wrapToPi(near.pose.phi - truth.phi)), 0.0, 0.5);
	// the same peak as the search's, to a few millimetres and the same score
	EXPECT_NEAR(near.pose.x, searched.pose.x, 0.01);
	EXPECT_NEAR(near.pose.y, searched.pose.y, 0.01);
	EXPECT_NEAR(near.score, searched.score, 0.01);
	EXPECT_GT(near.angle_step_rad, 0.0);
	EXPECT_EQ(near.rotations, 5u);
	EXPECT_LT(near.nodes_scored, 200u);  // the full search's window: 81 rotations
	// its covariance is the score surface's, as for a searched match
	const Eigen::Matrix3d cov = matcher.covarianceOf(scan, near);
	EXPECT_LT(std::sqrt(cov(0, 0)), 0.05);
	EXPECT_GT(cov.determinant(), 0.0);
	// 1.5 m off, two cells cannot reach the room's fit
	const auto off = matcher.matchNear(scan, {truth.x + 1.5, truth.y, truth.phi}, 0.55);
	EXPECT_FALSE(off.found);
}

TEST(CorrelativeScanMatcher, NoMatchOutsideTheWindowOrInAnotherPlace)
{
	std::mt19937_64 rng(8);
	const auto world = irregularRoom();
	CCorrelativeScanMatcher matcher;  // window 1 m / 30 deg
	matcher.setReference(roomReference(world, rng));
	const TPose2D frame{3.0, 3.5, 0.0}, robot{4.2, 4.4, 0.6};
	const TPose2D truth = relativePose(frame, robot);
	// true pose 2.5 m away from the guess: the best in the window is far worse than the truth's score
	const auto query = scanPoints(world, robot, rng);
	const double trueScore = matcher.scoreAt(query, truth);
	EXPECT_GT(trueScore, 0.7);
	const auto far = matcher.match(query, {truth.x + 2.5, truth.y, truth.phi});
	EXPECT_TRUE(!far.found || far.score < 0.7 * trueScore) << far.score;
	// a scan from a different room does not match
	hslam::sim::CWorld other;
	addBox(other, 0, 0, 4, 12);
	const auto wrong = matcher.match(scanPoints(other, {2, 6, 0.3}, rng), truth);
	EXPECT_TRUE(!wrong.found || wrong.score < 0.7 * trueScore) << wrong.score;
}

TEST(CorrelativeScanMatcher, SecondPeakFoundOutsideAnExclusion)
{
	const auto [matcher, query] = mirroredRoom();
	const TPose2D robot{0, 0, 0};
	const auto best = matcher.match(query, robot, {0.3, M_PI});
	ASSERT_TRUE(best.found);
	TSearchExclusion ex{best.pose, 0.5, mrpt::DEG2RAD(10.0)};
	const auto second = matcher.match(query, robot, {0.3, M_PI}, &ex, 0.0);
	ASSERT_TRUE(second.found);
	EXPECT_GT(second.score, 0.6);
	EXPECT_GT(std::abs(mrpt::math::wrapToPi(second.pose.phi - best.pose.phi)), mrpt::DEG2RAD(10.0));
}

TEST(CorrelativeScanMatcher, ThinnedSecondSearchFindsThePeakOnTheSearchQuery)
{
	// [loop_closure] ambiguity_thinned: the second search scores the thinned
	// query against the best leaf's score on that same query
	const auto [matcher, query] = mirroredRoom();
	const TPose2D robot{0, 0, 0};
	const auto best = matcher.match(query, robot, {0.3, M_PI});
	ASSERT_TRUE(best.found);
	EXPECT_GT(best.search_score, 0.6);
	EXPECT_LE(best.search_score, 1.0);
	TSearchExclusion ex{best.pose, 0.5, mrpt::DEG2RAD(10.0), true, true};
	const auto second = matcher.match(query, robot, {0.3, M_PI}, &ex, 0.75 * best.search_score);
	ASSERT_TRUE(second.found);
	EXPECT_LT(second.search_points, second.query_points);  // thinned, as the first search was
	EXPECT_EQ(second.search_points, best.search_points);
	EXPECT_GT(std::abs(mrpt::math::wrapToPi(second.pose.phi - best.pose.phi)), mrpt::DEG2RAD(10.0));
	// every point, as without the option: no thinning
	ex.thinned_query = false;
	EXPECT_EQ(matcher.match(query, robot, {0.3, M_PI}, &ex, 0.75 * best.score).search_points, best.query_points);
}
