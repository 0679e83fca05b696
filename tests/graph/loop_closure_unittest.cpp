/* CGraphBackend + CLoopClosureDetector on simulated runs with exact ground
 * truth: a drifted loop is closed; identical rooms are not confused. */
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>

#include "sim_trajectory.h"

using namespace hslam::graph;
using namespace hslam::graph::testing;
using mrpt::math::TPoint2D;

namespace
{
/** A 3 m wide corridor around a 24 x 14 m block, with pillars, boxes and
 * recesses at irregular places so that every place looks different. */
hslam::sim::CWorld loopCorridor()
{
	hslam::sim::CWorld w;
	addPolygon(w, {{0, 0}, {24, 0}, {24, 14}, {0, 14}});
	addPolygon(w, {{3, 3}, {21, 3}, {21, 11}, {3, 11}});
	addBox(w, 5.0, 0.0, 5.6, 0.5);
	addBox(w, 9.3, 2.4, 10.5, 3.0);
	addBox(w, 14.0, 0.0, 14.3, 0.9);
	addBox(w, 23.2, 4.0, 24.0, 5.5);
	addBox(w, 21.0, 8.0, 21.5, 8.3);
	addBox(w, 17.0, 13.3, 19.0, 14.0);
	addBox(w, 11.0, 11.0, 11.4, 11.8);
	addBox(w, 6.5, 13.0, 7.0, 14.0);
	addBox(w, 0.0, 9.0, 0.7, 9.4);
	addBox(w, 2.5, 5.0, 3.0, 6.5);
	for (const auto& c : {TPoint2D{7.5, 1.2}, TPoint2D{18.2, 2.0}, TPoint2D{22.5, 10.0}, TPoint2D{13.0, 12.6},
						  TPoint2D{1.2, 4.0}, TPoint2D{2.0, 12.0}})
		w.addCircle({c, 0.15, {}});
	return w;
}

std::vector<TPoint2D> loopWaypoints()
{
	// once around plus a second pass over the start (revisits)
	return {{1.5, 1.5}, {22.5, 1.5}, {22.5, 12.5}, {1.5, 12.5}, {1.5, 1.5}, {22.5, 1.5}, {22.5, 6.0}};
}

void expectClosuresNearTruth(const TRunResult& r, size_t& accepted)
{
	accepted = 0;
	for (const auto& c : r.closures)
	{
		if (!c.accepted) continue;
		++accepted;
		double xy, yaw;
		closureError(c, r.truth, xy, yaw);
		EXPECT_LT(xy, 0.2) << "closure " << c.query_keyframe_id << " -> " << c.anchor_keyframe_id;
		EXPECT_LT(mrpt::RAD2DEG(yaw), 2.0) << "closure " << c.query_keyframe_id << " -> " << c.anchor_keyframe_id;
	}
}
/** The drifted loop through the corridor, run with the given detector
 * options; `skippedWide`, if given, gets the detector's skippedRecentWide(). */
TRunResult runLoopWith(const TLoopClosureOptions& options, size_t* skippedWide = nullptr)
{
	CGraphBackend backend({}, options);
	auto r = runBackend(loopCorridor(), keyframePath(loopWaypoints()), TFrontEndErrors{}, backend);
	if (skippedWide) *skippedWide = backend.detector().skippedRecentWide();
	return r;
}
}  // namespace

TEST(LoopClosure, DriftedLoopIsClosedAndAteDrops)
{
	const auto world = loopCorridor();
	const auto truth = keyframePath(loopWaypoints());
	CGraphBackend backend;
	const auto r = runBackend(world, truth, TFrontEndErrors{}, backend);
	const double before = ate_m(r.frontend, truth), after = ate_m(r.optimized, truth);
	size_t accepted = 0;
	expectClosuresNearTruth(r, accepted);
	std::cout << "keyframes " << truth.size() << ", ATE before " << before << " m, after " << after << " m, closures "
			  << accepted << " accepted of " << r.closures.size() << " tested, optimisations "
			  << r.timing.optimizations << ", skipped " << backend.detector().skippedLittleInformation() << ", back-end " << r.timing.total_ms / truth.size() << " ms/keyframe\n";
	EXPECT_GT(before, 1.0);  // the drift is real
	EXPECT_GE(accepted, 5u);
	// once the loop is closed, the second pass over the start is known to the
	// graph as well as a closure would tell it: those candidates are skipped
	EXPECT_GT(backend.detector().skippedLittleInformation(), 0u);
	// measured 0.236 m (30 closures, 3 candidates skipped as uninformative;
	// loop edges at 10x the score-surface covariance, [graph]
	// loop_edge_covariance_factor); at 1x: 0.232 m (16 closures, 29 skipped);
	// earlier: 0.260 m (20 closures, 40 candidates skipped as uninformative);
	// every candidate tested with the full query: 0.203 m (41); thinned
	// search alone 0.248 m (41); gate 0.6 / 0.75 nats: 0.209 / 0.176 m. This
	// front-end has a systematic 1 % scale error that closures only at some
	// places cannot remove, and the residual moves with which closures are
	// taken (each is checked above: within 0.2 m / 2 deg). 0.084 m (47) with
	// the former chain-difference covariance, whose windows and gate differed
	// (docs/loop-closure.md, "Relative covariance", "Cost").
	EXPECT_LT(after, 0.3);
}

TEST(LoopClosure, ClosuresThatAgreeWaitForTheNextOptimisation)
{
	// [graph] optimize_min_closure_chi2: a closure whose edge already agrees
	// with the graph is added without an optimisation of its own; the next
	// disagreeing closure's optimisation, or the flush at the end of the run,
	// includes it. Far fewer optimisations, the same loop closed as well.
	const auto world = loopCorridor();
	const auto truth = keyframePath(loopWaypoints());
	double ate[2];
	TBackendTiming timing[2];
	const double chi2[2] = {0.0, 2.0};
	for (int k = 0; k < 2; ++k)
	{
		TGraphBackendOptions go;
		go.optimize_min_closure_chi2 = chi2[k];
		CGraphBackend backend(go, {});
		const auto r = runBackend(world, truth, TFrontEndErrors{}, backend);
		ate[k] = ate_m(r.optimized, truth), timing[k] = r.timing;
		size_t accepted = 0;
		expectClosuresNearTruth(r, accepted);
		std::cout << "optimize_min_closure_chi2 " << chi2[k] << ": ATE " << ate[k] << " m, " << accepted
				  << " closures, " << timing[k].optimizations << " optimisations, " << timing[k].closures_deferred
				  << " closures waited\n";
		// after the flush nothing is left to optimise: one more solve moves no keyframe
		auto again = backend.graph();
		again.optimize();
		for (size_t n = 0; n < again.nodeCount(); ++n)
		{
			const auto& a = again.nodes()[n].pose;
			const auto& b = backend.graph().nodes()[n].pose;
			ASSERT_LT(std::hypot(a.x - b.x, a.y - b.y), 0.005) << "chi2 " << chi2[k] << ", node " << n;
		}
	}
	EXPECT_EQ(timing[0].closures_deferred, 0u);
	EXPECT_GT(timing[1].closures_deferred, 5u);
	// measured: 18 optimisations -> 10 (the flush included), 14 closures
	// waited; ATE 0.2364 -> 0.2361 m with the same 30 closures
	EXPECT_LT(timing[1].optimizations * 3, timing[0].optimizations * 2);
	EXPECT_LT(ate[1], 0.3);
	EXPECT_LT(std::abs(ate[1] - ate[0]), 0.01);
}

TEST(LoopClosure, LoopEdgeCovarianceIsTheClosuresTimesTheFactor)
{
	// [graph] loop_edge_covariance_factor: every accepted closure's edge
	// carries the inverse of factor x its score-surface covariance (the
	// default 10, and 1 = as measured).
	const auto world = loopCorridor();
	const auto truth = keyframePath(loopWaypoints());
	for (const double factor : {10.0, 1.0})
	{
		TGraphBackendOptions go;
		go.loop_edge_covariance_factor = factor;
		CGraphBackend backend(go, {});
		runBackend(world, truth, TFrontEndErrors{}, backend);
		size_t checked = 0;
		for (const auto& c : backend.closures())
		{
			if (!c.accepted || c.edge < 0) continue;
			const Eigen::Matrix3d product = backend.graph().edges()[static_cast<size_t>(c.edge)].information * c.covariance;
			EXPECT_TRUE(product.isApprox(Eigen::Matrix3d::Identity() / factor, 1e-6)) << "factor " << factor;
			++checked;
		}
		EXPECT_GE(checked, 5u) << "factor " << factor;
	}
	EXPECT_DOUBLE_EQ(TGraphBackendOptions{}.loop_edge_covariance_factor, 10.0);
}

TEST(LoopClosure, CandidatesVerifiedSideBySideGiveTheSameClosures)
{
	// [loop_closure] search_threads: a keyframe's candidates are verified
	// on several threads; they are independent, so one thread and four give
	// the same closures (same order, same figures) and the same graph.
	const auto world = loopCorridor();
	const auto truth = keyframePath(loopWaypoints());
	std::vector<TLoopClosure> byThreads[2];
	std::vector<TGraphNode> nodes[2];
	const int threads[2] = {1, 4};
	for (int k = 0; k < 2; ++k)
	{
		TLoopClosureOptions lo;
		lo.search_threads = threads[k];
		CGraphBackend backend({}, lo);
		runBackend(world, truth, TFrontEndErrors{}, backend);
		byThreads[k] = backend.closures();
		nodes[k] = backend.graph().nodes();
	}
	ASSERT_GE(byThreads[0].size(), 20u);
	ASSERT_EQ(byThreads[0].size(), byThreads[1].size());
	for (size_t i = 0; i < byThreads[0].size(); ++i)
	{
		const auto &a = byThreads[0][i], &b = byThreads[1][i];
		EXPECT_EQ(a.reason, b.reason) << i;
		EXPECT_EQ(a.submap, b.submap) << i;
		EXPECT_EQ(a.score, b.score) << i;
		EXPECT_TRUE(a.relative.x == b.relative.x && a.relative.y == b.relative.y && a.relative.phi == b.relative.phi);
	}
	ASSERT_EQ(nodes[0].size(), nodes[1].size());
	for (size_t n = 0; n < nodes[0].size(); ++n)
		EXPECT_TRUE(nodes[0][n].pose.x == nodes[1][n].pose.x && nodes[0][n].pose.phi == nodes[1][n].pose.phi) << n;
}

TEST(LoopClosure, SearchStopsAtTheFirstAcceptedClosureOfAKeyframe)
{
	// The same drifted loop matched with every candidate of a keyframe and
	// with the search ended at its first accepted closure: fewer matches, no
	// keyframe with two accepted closures, the loop still closed.
	const auto truth = keyframePath(loopWaypoints());
	TLoopClosureOptions lc;
	const auto all = runLoopWith(lc);
	lc.max_closures_per_keyframe = 1;
	const auto first = runLoopWith(lc);
	std::map<size_t, int> acceptedPerQuery;
	for (const auto& c : first.closures) acceptedPerQuery[c.query_node] += c.accepted ? 1 : 0;
	for (const auto& [query, n] : acceptedPerQuery) EXPECT_LE(n, 1) << "keyframe " << query;
	size_t accepted = 0;
	expectClosuresNearTruth(first, accepted);
	std::cout << "matches " << all.closures.size() << " -> " << first.closures.size() << ", ATE "
			  << ate_m(all.optimized, truth) << " -> " << ate_m(first.optimized, truth) << " m\n";
	EXPECT_LT(first.closures.size(), all.closures.size());
	EXPECT_GE(accepted, 5u);
	EXPECT_LT(ate_m(first.optimized, truth), 0.3);
}

TEST(LoopClosure, LowScoreWidestSearchIsRepeatedOnlyAfterTheGivenKeyframes)
{
	// The drifted loop: with retest_wide_after_keyframes = 3, a submap whose
	// search over the widest window ended with a low score is not searched
	// over it again at the next two keyframes; the loop is still closed.
	// (Measured: 215 -> 176 matches, 26 over the widest window, 39 skipped;
	// ATE 0.236 m both.)
	TLoopClosureOptions lc;
	std::vector<TRunResult> runs;  // every keyframe, then every third
	size_t skipped = 0;
	for (const int n : {1, 3})
		lc.retest_wide_after_keyframes = n, runs.push_back(runLoopWith(lc, n == 3 ? &skipped : nullptr));
	const TRunResult &every = runs[0], &spaced = runs[1];
	std::map<size_t, size_t> lowScoreWideAt;  // submap -> query node
	size_t wide = 0;
	for (const auto& c : spaced.closures)
	{
		if (c.window_xy_m < lc.max_window_xy_m) continue;
		++wide;
		const auto last = lowScoreWideAt.find(c.submap);
		if (last != lowScoreWideAt.end())
		{
			EXPECT_GE(c.query_node, last->second + 3) << "submap " << c.submap;
		}
		if (c.reason == "low score") lowScoreWideAt[c.submap] = c.query_node;
	}
	size_t accepted = 0;
	expectClosuresNearTruth(spaced, accepted);
	std::cout << "matches " << every.closures.size() << " -> " << spaced.closures.size() << " (" << wide
			  << " widest, " << skipped << " skipped), ATE " << ate_m(every.optimized, every.truth) << " -> "
			  << ate_m(spaced.optimized, spaced.truth) << " m\n";
	EXPECT_GT(wide, 0u);
	EXPECT_GT(skipped, 0u);
	EXPECT_LT(spaced.closures.size(), every.closures.size());
	EXPECT_GE(accepted, 5u);
	EXPECT_LT(ate_m(spaced.optimized, spaced.truth), 0.3);
}

TEST(LoopClosure, ClosuresAreTrackedFromTheKeyframeBeforeOnlyAfterConfirmation)
{
	// [loop_closure] max_tracked_in_a_row: a submap whose closure the
	// keyframe before kept is verified from that closure (a search of two
	// cells and two rotation steps, no second-peak search). Only kept (confirmed) closures are followed, at
	// most max_tracked_in_a_row in a row, and the loop closes as well.
	const auto truth = keyframePath(loopWaypoints());
	TLoopClosureOptions lc;
	lc.max_tracked_in_a_row = 0;
	const auto searched = runLoopWith(lc);
	lc.max_tracked_in_a_row = 4;
	const auto tracked = runLoopWith(lc);
	EXPECT_EQ(TLoopClosureOptions{}.max_tracked_in_a_row, 0);  // off by default: docs/loop-closure.md
	size_t trackedCount = 0, accepted = 0;
	for (const auto& c : searched.closures) EXPECT_EQ(c.tracked_in_a_row, 0);
	for (const auto& c : tracked.closures)
	{
		if (c.tracked_in_a_row == 0) continue;
		++trackedCount;
		EXPECT_LE(c.tracked_in_a_row, 4);
		// the closure it follows: the same submap, the keyframe before, kept in the graph
		const auto before = std::find_if(tracked.closures.begin(), tracked.closures.end(), [&](const TLoopClosure& b) {
			return b.query_node + 1 == c.query_node && b.submap == c.submap && b.accepted &&
				   b.tracked_in_a_row + 1 == c.tracked_in_a_row;
		});
		EXPECT_NE(before, tracked.closures.end()) << "keyframe " << c.query_keyframe_id;
	}
	expectClosuresNearTruth(tracked, accepted);  // every accepted closure, tracked or searched
	const double ateSearched = ate_m(searched.optimized, truth), ateTracked = ate_m(tracked.optimized, truth);
	std::cout << "tracked closures " << trackedCount << " of " << tracked.closures.size() << " tested, ATE "
			  << ateSearched << " -> " << ateTracked << " m\n";
	EXPECT_GE(trackedCount, 5u);
	EXPECT_GE(accepted, 5u);
	EXPECT_LT(ateTracked, 0.3);
	EXPECT_LT(ateTracked, ateSearched + 0.05);
}

namespace
{
/** Room of 8 x 6 m at x0 (y 2.5..8.5) with a door in its bottom wall and
 * the same furniture in every copy. */
void addRoom(hslam::sim::CWorld& w, double x0)
{
	w.addSegment({{x0, 2.5}, {x0 + 5.6, 2.5}, {}});
	w.addSegment({{x0 + 6.8, 2.5}, {x0 + 8, 2.5}, {}});
	w.addSegment({{x0 + 8, 2.5}, {x0 + 8, 8.5}, {}});
	w.addSegment({{x0 + 8, 8.5}, {x0, 8.5}, {}});
	w.addSegment({{x0, 8.5}, {x0, 2.5}, {}});
	addBox(w, x0 + 3.5, 5.5, x0 + 4.5, 6.1);
	addBox(w, x0 + 7.3, 7.3, x0 + 8.0, 8.0);
	addBox(w, x0, 3.5, x0 + 0.5, 4.2);
	w.addCircle({{x0 + 1.0, 7.6}, 0.2, {}});
	w.addCircle({{x0 + 4.0, 3.4}, 0.15, {}});
}

/** Two identical rooms (x 0..8 and 14..22) joined by a corridor below them. */
hslam::sim::CWorld identicalRooms()
{
	hslam::sim::CWorld w;
	addRoom(w, 0.0);
	addRoom(w, 14.0);
	addPolygon(w, {{-1, 0}, {23, 0}, {23, 2.5}, {22, 2.5}});  // corridor: bottom, right end
	w.addSegment({{-1, 0}, {-1, 2.5}, {}});
	w.addSegment({{-1, 2.5}, {0, 2.5}, {}});
	w.addSegment({{8, 2.5}, {14, 2.5}, {}});
	return w;
}
}  // namespace

TEST(LoopClosure, IdenticalRoomIsNotTakenForTheOther)
{
	const auto world = identicalRooms();
	const std::vector<TPoint2D> roomA = {{2, 4.5}, {6.2, 4.5}, {6.2, 7.0}, {2, 7.0}, {2, 4.5}, {6.2, 4.5}};
	std::vector<TPoint2D> waypoints = roomA;
	waypoints.insert(waypoints.end(), {{6.2, 1.25}, {20.2, 1.25}});
	for (const auto& p : roomA) waypoints.push_back({p.x + 14.0, p.y});
	std::reverse(waypoints.end() - static_cast<long>(roomA.size()), waypoints.end());  // enter B at its door side
	const auto truth = keyframePath(waypoints);
	size_t firstInB = 0;
	while (truth[firstInB].x < 13.0) ++firstInB;
	// a search wide enough to see room A from room B (as after a large drift)
	TLoopClosureOptions lc;
	lc.overlap_distance_m = 20.0;
	lc.min_window_xy_m = lc.max_window_xy_m = 16.0;
	lc.detect_every_n_keyframes = 2;
	CGraphBackend backend({}, lc);
	const auto r = runBackend(world, truth, TFrontEndErrors{}, backend, 3);
	size_t wrongPlaceMatched = 0, crossAccepted = 0, accepted = 0;
	std::map<std::string, int> reasons;
	for (const auto& c : r.closures)
	{
		const bool cross = c.query_node >= firstInB && c.anchor_node < firstInB;
		++reasons[(cross ? "room B -> room A: " : "same room: ") + c.reason];
		if (cross && c.score >= lc.min_score) ++wrongPlaceMatched;
		if (cross && c.accepted) ++crossAccepted;
	}
	expectClosuresNearTruth(r, accepted);
	for (const auto& [why, n] : reasons) std::cout << why << ": " << n << "\n";
	std::cout << "ATE before " << ate_m(r.frontend, truth) << " m, after " << ate_m(r.optimized, truth) << " m\n";
	EXPECT_GT(wrongPlaceMatched, 0u);  // the wide search did find room A from room B ...
	EXPECT_EQ(crossAccepted, 0u);  // ... and verification refused it
	EXPECT_LT(ate_m(r.optimized, truth), ate_m(r.frontend, truth) + 0.02);
}
