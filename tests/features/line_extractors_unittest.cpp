/* All three line extractors on the same exact synthetic scenes: counts of
 * lines, endpoint errors, vertical/horizontal walls, gaps, occlusions,
 * invalid beams, sensor mounting. */
#include "line_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/benchdata/line_scenes.h>
#include <hslam/benchdata/line_scoring.h>
#include <hslam/features/scan_points.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>

using namespace hslam::features;
using namespace hslam::benchdata;
using namespace hslam::features::test;

class AllExtractors : public ::testing::TestWithParam<std::string>
{
};

INSTANTIATE_TEST_SUITE_P(Methods, AllExtractors, ::testing::Values("derivative", "iep", "ransac"));

TEST_P(AllExtractors, BoxRoomNoiselessExactLinesAndEndpoints)
{
	const auto ex = defaultExtractor(GetParam());
	const auto sim = simulate(boxRoom(0));
	const TLineSegmentList lines = ex->extract(sim.scan);
	const auto truth = visibleWalls(sim, 5, 0.2);
	ASSERT_EQ(truth.size(), 3u);
	const TLineScore score = scoreLines(truth, lines);
	EXPECT_EQ(lines.size(), 3u);
	EXPECT_EQ(score.found, 3u);
	EXPECT_EQ(score.false_positives, 0u);
	// one beam spacing at the far corner (4, -3) is 5 m * 1 deg / cos(37 deg) ~ 0.11 m;
	// derivative and IEP end exactly on the corner beams, RANSAC may lose a corner point
	const double tolerance = GetParam() == "ransac" ? 0.12 : 1e-5;
	EXPECT_LT(score.max_endpoint_error_m, tolerance);
	ASSERT_EQ(lines.size(), 3u);
	// right wall y = -3 (horizontal), front x = 4 (vertical), left y = 2
	EXPECT_NEAR(lines[0].rho_m, 3.0, 1e-6);
	EXPECT_NEAR(lines[0].alpha_rad, -M_PI / 2, 1e-6);
	EXPECT_NEAR(lines[1].rho_m, 4.0, 1e-6);
	EXPECT_NEAR(lines[1].alpha_rad, 0.0, 1e-6);
	EXPECT_FALSE(lines[1].slopeIntercept().has_value()) << "vertical wall has no slope/intercept";
	const auto left = lines[2].slopeIntercept();
	ASSERT_TRUE(left.has_value());
	EXPECT_NEAR(left->first, 0.0, 1e-6);
	EXPECT_NEAR(left->second, 2.0, 1e-6);
	for (const auto& l : lines) EXPECT_LT(l.fit_rms_m, 1e-6);
	// the first beam (-90 deg) hits the right wall at (0, -3), the last (+90) the left at (0, 2)
	EXPECT_EQ(lines[0].first_beam, 0u);
	EXPECT_EQ(lines[2].last_beam, 180u);
	// corners are wall ends, the scan border is not
	EXPECT_TRUE(lines[0].p0_occluded);
	EXPECT_FALSE(lines[0].p1_occluded);
	EXPECT_FALSE(lines[1].p0_occluded);
	EXPECT_FALSE(lines[1].p1_occluded);
	EXPECT_FALSE(lines[2].p0_occluded);
	EXPECT_TRUE(lines[2].p1_occluded);
}

TEST_P(AllExtractors, BoxRoomWithSickNoise)
{
	const auto ex = defaultExtractor(GetParam());
	TLineScore total;
	const int trials = 20;
	for (int seed = 1; seed <= trials; ++seed)
	{
		const auto sim = simulate(boxRoom(0.01), static_cast<uint32_t>(seed));
		const TLineScore s = scoreLines(visibleWalls(sim, 5, 0.2), ex->extract(sim.scan));
		total.found += s.found;
		total.false_positives += s.false_positives;
		total.sum_endpoint_error_m += s.sum_endpoint_error_m;
	}
	// measured: derivative and IEP 60/60, 0 FP, ~1.6 cm; RANSAC 60/60, 0 FP, ~2 cm
	EXPECT_GE(total.found, 58u) << GetParam();
	EXPECT_LE(total.false_positives, 2u) << GetParam();
	EXPECT_LT(total.meanEndpointError_m(), 0.04) << GetParam();
}

TEST_P(AllExtractors, CornersWithinOneBeam)
{
	const auto ex = defaultExtractor(GetParam());
	for (int seed = 0; seed <= 10; ++seed)  // seed 0: noiseless
	{
		const auto sim = simulate(boxRoom(seed == 0 ? 0.0 : 0.01), static_cast<uint32_t>(seed));
		const TLineSegmentList lines = ex->extract(sim.scan);
		ASSERT_EQ(lines.size(), 3u) << GetParam() << " seed " << seed;
		// the true end beams of the walls: right 0-53, front 54-116, left 117-180
		EXPECT_LE(std::abs(static_cast<int>(lines[0].last_beam) - 53), 1) << GetParam() << " seed " << seed;
		EXPECT_LE(std::abs(static_cast<int>(lines[1].first_beam) - 54), 1) << GetParam() << " seed " << seed;
		EXPECT_LE(std::abs(static_cast<int>(lines[1].last_beam) - 116), 1) << GetParam() << " seed " << seed;
		EXPECT_LE(std::abs(static_cast<int>(lines[2].first_beam) - 117), 1) << GetParam() << " seed " << seed;
		if (seed == 0 && GetParam() != "ransac")
		{
			EXPECT_EQ(lines[0].last_beam, 53u);
			EXPECT_EQ(lines[1].first_beam, 54u);
			EXPECT_EQ(lines[1].last_beam, 116u);
			EXPECT_EQ(lines[2].first_beam, 117u);
		}
	}
}

TEST_P(AllExtractors, SeparateWallsAcrossGapsStaySeparate)
{
	const auto ex = defaultExtractor(GetParam());
	const auto scenes = thesisTable3Scenes(0.0, 0.0);
	const auto& walls = scenes[2].walls;  // three walls with open space between them
	const auto sim = simulate(walls);
	const auto truth = visibleWalls(sim, 5, 0.2);
	ASSERT_EQ(truth.size(), 3u);
	const TLineSegmentList lines = ex->extract(sim.scan);
	const TLineScore score = scoreLines(truth, lines);
	EXPECT_EQ(score.found, 3u);
	EXPECT_EQ(score.false_positives, 0u);
	for (const auto& l : lines)
	{
		bool insideOne = false;
		for (const auto& t : truth) insideOne |= l.first_beam >= t.first_beam && l.last_beam <= t.last_beam;
		EXPECT_TRUE(insideOne) << "line over beams " << l.first_beam << "-" << l.last_beam << " bridges a gap";
		// beyond each wall's end the beams see nothing (invalid): the end is not a known wall end
		EXPECT_TRUE(l.p0_occluded);
		EXPECT_TRUE(l.p1_occluded);
	}
}

TEST_P(AllExtractors, PillarInFrontOfWallOccludesIt)
{
	const auto ex = defaultExtractor(GetParam());
	// wall x = 4 (y in [-5, 5], ends at +-51.3 deg), pillar face x = 2, y in [-0.3, 0.3]
	const std::vector<TWall> walls{{{4, -5}, {4, 5}, 0}, {{2, -0.3}, {2, 0.3}, 0}};
	const auto sim = simulate(walls);
	const auto truth = visibleWalls(sim, 5, 0.2);
	ASSERT_EQ(truth.size(), 3u);  // wall right part, pillar, wall left part
	const TLineSegmentList lines = ex->extract(sim.scan);
	const TLineScore score = scoreLines(truth, lines);
	EXPECT_EQ(score.found, 3u);
	EXPECT_EQ(score.false_positives, 0u) << "the two wall parts must not become one line through the pillar";
	ASSERT_EQ(lines.size(), 3u);
	EXPECT_NEAR(lines[1].rho_m, 2.0, 1e-6);
	// wall parts: outer ends see nothing beyond (invalid), inner ends hidden by the pillar
	EXPECT_TRUE(lines[0].p0_occluded);
	EXPECT_TRUE(lines[0].p1_occluded);
	EXPECT_TRUE(lines[2].p0_occluded);
	EXPECT_TRUE(lines[2].p1_occluded);
	// the pillar's ends are real: the beams beside it see the wall behind
	EXPECT_FALSE(lines[1].p0_occluded);
	EXPECT_FALSE(lines[1].p1_occluded);
}

TEST_P(AllExtractors, InvalidBeamsMakeNoCornersAndNoLines)
{
	const auto ex = defaultExtractor(GetParam());
	auto sim = simulate(boxRoom(0));
	auto& scan = sim.scan;
	const float nan = std::numeric_limits<float>::quiet_NaN();
	for (size_t i : {70, 71, 72}) scan.setScanRange(i, nan);  // NaN (flag still on)
	scan.setScanRange(76, 0.0f);  // zero
	scan.setScanRange(80, scan.maxRange);  // "no echo" value
	scan.setScanRange(84, 2 * scan.maxRange);  // beyond range
	scan.setScanRange(88, -1.0f);  // negative
	for (size_t i = 92; i < 102; ++i)  // flag off with a plausible-looking range: a phantom wall at 1 m
	{
		scan.setScanRange(i, 1.0f);
		scan.setScanRangeValidity(i, false);
	}
	const std::set<size_t> invalid{70, 71, 72, 76, 80, 84, 88, 92, 93, 94, 95, 96, 97, 98, 99, 100, 101};
	const TLineSegmentList lines = ex->extract(scan);
	ASSERT_GE(lines.size(), 3u) << GetParam();
	// side walls unchanged
	EXPECT_EQ(lines.front().first_beam, 0u);
	EXPECT_NEAR(lines.front().rho_m, 3.0, 1e-6);
	EXPECT_EQ(lines.back().last_beam, 180u);
	EXPECT_NEAR(lines.back().rho_m, 2.0, 1e-6);
	size_t frontPoints = 0;
	for (const auto& l : lines)
	{
		// no phantom line: every line lies exactly on one of the three walls
		const bool onWall = (std::abs(l.rho_m - 3) < 1e-6 && std::abs(l.alpha_rad + M_PI / 2) < 1e-6) ||
							(std::abs(l.rho_m - 4) < 1e-6 && std::abs(l.alpha_rad) < 1e-6) ||
							(std::abs(l.rho_m - 2) < 1e-6 && std::abs(l.alpha_rad - M_PI / 2) < 1e-6);
		EXPECT_TRUE(onWall) << GetParam() << " phantom line rho " << l.rho_m << " alpha " << l.alpha_rad;
		EXPECT_LT(l.fit_rms_m, 1e-6);
		// invalid beams are never in a line
		EXPECT_EQ(invalid.count(l.first_beam) + invalid.count(l.last_beam), 0u);
		size_t invalidInside = 0;
		for (size_t b : invalid) invalidInside += b > l.first_beam && b < l.last_beam;
		EXPECT_LE(l.point_count, l.last_beam - l.first_beam + 1 - invalidInside);
		if (std::abs(l.rho_m - 4) < 1e-6)
		{
			frontPoints += l.point_count;
			// the front wall may be cut only at invalid beams (no phantom corner elsewhere)
			if (l.first_beam != 54u)
			{
				EXPECT_TRUE(invalid.count(l.first_beam - 1)) << GetParam() << " " << l.first_beam;
			}
			if (l.last_beam != 116u)
			{
				EXPECT_TRUE(invalid.count(l.last_beam + 1)) << GetParam() << " " << l.last_beam;
			}
		}
	}
	// the long valid stretches of the front wall (54-69, 102-116) are on lines
	EXPECT_GE(frontPoints, 16u + 15u) << GetParam();
}

TEST_P(AllExtractors, SingleDropoutsDoNotSplitAWall)
{
	const auto ex = defaultExtractor(GetParam());
	auto sim = simulate(boxRoom(0.005), 3);
	sim.scan.setScanRange(85, std::numeric_limits<float>::quiet_NaN());
	sim.scan.setScanRangeValidity(100, false);
	const TLineSegmentList lines = ex->extract(sim.scan);
	const TLineScore score = scoreLines(visibleWalls(simulate(boxRoom(0)), 5, 0.2), lines);
	EXPECT_EQ(score.found, 3u) << GetParam();
	EXPECT_EQ(score.false_positives, 0u) << GetParam();
	ASSERT_EQ(lines.size(), 3u);
	EXPECT_EQ(lines[1].point_count, 63u - 2u);
}

TEST_P(AllExtractors, ScansWithoutEnoughValidPointsGiveNoLines)
{
	const auto ex = defaultExtractor(GetParam());
	auto sim = simulate(boxRoom(0));
	for (size_t i = 0; i < sim.scan.getScanSize(); ++i) sim.scan.setScanRangeValidity(i, false);
	EXPECT_TRUE(ex->extract(sim.scan).empty());
	for (size_t i = 100; i < 103; ++i) sim.scan.setScanRangeValidity(i, true);  // 3 < min_points
	EXPECT_TRUE(ex->extract(sim.scan).empty());
	mrpt::obs::CObservation2DRangeScan empty;
	EXPECT_TRUE(ex->extract(empty).empty());
}

TEST_P(AllExtractors, LinesAreInTheRobotFrame)
{
	const auto ex = defaultExtractor(GetParam());
	// The laser sits at (0.3, 0.1) on the robot, turned 90 deg left; the
	// robot is at the origin. Casting from the laser's world pose and then
	// declaring that pose as sensorPose must give the walls in robot = world frame.
	const mrpt::poses::CPose2D laser(0.3, 0.1, M_PI / 2);
	const std::vector<TWall> walls{{{-3, 3}, {2, 3}, 0}, {{2, 3}, {2, 0.5}, 0}};  // y = 3 ahead of the laser, x = 2 on its right
	auto sim = simulate(walls, 1, laser);
	sim.scan.sensorPose = mrpt::poses::CPose3D(laser);
	const TLineSegmentList lines = ex->extract(sim.scan);
	ASSERT_EQ(lines.size(), 2u);
	EXPECT_NEAR(lines[0].rho_m, 2.0, 1e-6);  // x = 2 comes first (right of the laser, low beams)
	EXPECT_NEAR(lines[0].alpha_rad, 0.0, 1e-6);
	EXPECT_NEAR(lines[1].rho_m, 3.0, 1e-6);
	EXPECT_NEAR(lines[1].alpha_rad, M_PI / 2, 1e-6);
	EXPECT_NEAR(lines[0].p0.y, 0.5, 0.06);  // the end of the x = 2 wall
	EXPECT_NEAR(lines[0].p1.y, 3.0, 0.1);  // the corner, within one beam spacing (1 deg at 3.6 m)
	EXPECT_LT(lines[0].p1.y, 3.0 + 1e-6);
}

TEST_P(AllExtractors, ThesisTable3Scenes)
{
	const auto ex = defaultExtractor(GetParam());
	const auto scenes = thesisTable3Scenes(0.01, 0.03);
	// measured (10 views, default options): F1 derivative ~0.99, iep ~0.99, ransac ~0.8
	const double minF1 = GetParam() == "ransac" ? 0.6 : 0.95;
	TLineScore total;
	for (const auto& scene : scenes)
		for (int seed = 1; seed <= 10; ++seed)
		{
			const auto sim = simulate(scene.walls, static_cast<uint32_t>(seed));
			const TLineScore s = scoreLines(visibleWalls(sim, 5, 0.2), ex->extract(sim.scan));
			total.truth += s.truth;
			total.extracted += s.extracted;
			total.found += s.found;
		}
	EXPECT_GE(total.f1(), minF1) << GetParam() << " found " << total.found << "/" << total.truth << " of "
								 << total.extracted;
	EXPECT_EQ(total.truth, 10u * (10 + 2 + 3));
}

TEST_P(AllExtractors, GarbageScansNeverCrashAndGiveSaneLines)
{
	const auto ex = defaultExtractor(GetParam());
	std::mt19937 rng(11);
	std::uniform_real_distribution<float> range(-2.0f, 12.0f);
	std::uniform_int_distribution<int> kind(0, 9);
	for (int trial = 0; trial < 30; ++trial)
	{
		mrpt::obs::CObservation2DRangeScan scan;
		const size_t n = static_cast<size_t>(1 + trial * 13);  // 1 .. 378 beams
		scan.resizeScan(n);
		scan.aperture = static_cast<float>(M_PI);
		scan.maxRange = 10.0f;
		for (size_t i = 0; i < n; ++i)
		{
			const int k = kind(rng);
			const float r = k == 0   ? std::numeric_limits<float>::quiet_NaN()
							: k == 1 ? std::numeric_limits<float>::infinity()
							: k == 2 ? 0.0f
							: k <= 5 ? 3.0f  // runs of equal ranges: arcs, identical-looking points
									 : range(rng);
			scan.setScanRange(i, r);
			scan.setScanRangeValidity(i, kind(rng) != 0);
		}
		TLineSegmentList lines;
		ASSERT_NO_THROW(lines = ex->extract(scan)) << GetParam() << " trial " << trial;
		for (const auto& l : lines)
		{
			EXPECT_TRUE(std::isfinite(l.rho_m) && std::isfinite(l.alpha_rad) && std::isfinite(l.fit_rms_m));
			EXPECT_TRUE(std::isfinite(l.p0.x) && std::isfinite(l.p1.y));
			EXPECT_LT(l.last_beam, n);
			EXPECT_TRUE(hslam::common::isValidReturn(scan, l.first_beam) && hslam::common::isValidReturn(scan, l.last_beam));
		}
	}
}

TEST_P(AllExtractors, HalfDegreeScansGiveTheSameWalls)
{
	// 361 beams over 180 deg (as in the csail log): corners between beams 106/107 and 233/234
	const auto ex = defaultExtractor(GetParam());
	TScanLayout layout;
	layout.beams = 361;
	for (int seed = 0; seed <= 5; ++seed)
	{
		const auto sim = simulateScan(boxRoom(seed == 0 ? 0.0 : 0.01), mrpt::poses::CPose2D(), layout,
									  static_cast<uint32_t>(seed));
		const TLineSegmentList lines = ex->extract(sim.scan);
		const TLineScore score = scoreLines(visibleWalls(sim, 5, 0.2), lines);
		EXPECT_EQ(score.found, 3u) << GetParam() << " seed " << seed;
		EXPECT_EQ(score.false_positives, 0u) << GetParam() << " seed " << seed;
		ASSERT_EQ(lines.size(), 3u);
		EXPECT_LE(std::abs(static_cast<int>(lines[0].last_beam) - 106), 1) << GetParam() << " seed " << seed;
		EXPECT_LE(std::abs(static_cast<int>(lines[2].first_beam) - 234), 1) << GetParam() << " seed " << seed;
	}
}
