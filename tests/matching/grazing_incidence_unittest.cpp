/* pointsOffGrazingIncidence (libs/matching scan_points.h) on hand-built scans. */
#include <gtest/gtest.h>
#include <hslam/matching/scan_points.h>

#include <cmath>

using hslam::common::TScanPoints;
using hslam::matching::pointsOffGrazingIncidence;

namespace
{
constexpr double kDeg = M_PI / 180;

void addBeam(TScanPoints& s, size_t beam, double bearing_rad, double range_m)
{
	s.xy.push_back({range_m * std::cos(bearing_rad), range_m * std::sin(bearing_rad)});
	s.range_m.push_back(range_m);
	s.beam.push_back(beam);
}

/** A wall along y = 1 m seen from the origin by 1 deg beams at bearings
 * 0.5, 1.5, ..., 89.5 deg: beam k meets it at incidence 89.5 - k deg. */
TScanPoints wallScan()
{
	TScanPoints s;
	s.beam_step_rad = 1 * kDeg;
	for (size_t k = 0; k < 90; ++k)
	{
		const double bearing = (k + 0.5) * kDeg;
		addBeam(s, k, bearing, 1.0 / std::sin(bearing));
	}
	return s;
}
}  // namespace

TEST(GrazingIncidence, WallPointsBeyondTheIncidenceLimitAreLeftOut)
{
	// Beam k's nearer neighbour lies sin(1 deg) / (sin b_k sin b_k+1) away
	// along the wall; the limit is r_k (1 deg) / cos(80 deg). Kept iff
	// sin(b_k+1) >= cos(80 deg) sin(1 deg) / (1 deg) = 0.17364, i.e. b_k+1 >=
	// 10 deg: bearings 0.5 ... 8.5 deg (nine points) go, 9.5 deg on stay.
	const auto s = wallScan();
	const auto kept = pointsOffGrazingIncidence(s, 80 * kDeg);
	ASSERT_EQ(kept.size(), 81u);
	EXPECT_NEAR(std::atan2(kept.front().y, kept.front().x), 9.5 * kDeg, 1e-9);
	// at 60 deg: b_k+1 >= asin(0.5 x 0.99995) = 29.997 deg: bearings below 29.5 go
	EXPECT_EQ(pointsOffGrazingIncidence(s, 60 * kDeg).size(), 61u);
	EXPECT_EQ(pointsOffGrazingIncidence(s, 0).size(), 90u);  // off
}

TEST(GrazingIncidence, ThinObjectGoesLoneReturnStays)
{
	TScanPoints s;
	s.beam_step_rad = 1 * kDeg;
	// a pole at 2 m in front of a wall at 5 m: beams 0-2 on the wall, 3 on the pole, 4-6 on the wall
	for (size_t b = 0; b < 7; ++b) addBeam(s, b, b * kDeg, b == 3 ? 2.0 : 5.0);
	// a lone return: beams 8 and 10 invalid (no point), beam 9 at 7 m
	addBeam(s, 9, 9 * kDeg, 7.0);
	const auto kept = pointsOffGrazingIncidence(s, 80 * kDeg);
	ASSERT_EQ(kept.size(), 7u);  // the pole's point is a lone sample of its surface
	for (const auto& p : kept) EXPECT_GT(std::hypot(p.x, p.y), 4.9);
	EXPECT_NEAR(std::hypot(kept.back().x, kept.back().y), 7.0, 1e-9);  // nothing tells: kept
}

TEST(EveryKthPoint, KeepsAtMostTheLimitInScanOrder)
{
	// 1 081 points (0.25 deg over 270 deg) with a limit of 400: k = ceil(1081
	// / 400) = 3, points 0, 3, ..., 1080: 361 kept
	std::vector<mrpt::math::TPoint2D> points;
	for (int i = 0; i < 1081; ++i) points.push_back({static_cast<double>(i), 0.0});
	const auto kept = hslam::matching::everyKthPoint(points, 400);
	ASSERT_EQ(kept.size(), 361u);
	for (size_t j = 0; j < kept.size(); ++j) ASSERT_EQ(kept[j].x, 3.0 * static_cast<double>(j));
	// at or under the limit, and with no limit, every point stays
	EXPECT_EQ(hslam::matching::everyKthPoint(points, 1081).size(), 1081u);
	EXPECT_EQ(hslam::matching::everyKthPoint(points, 0).size(), 1081u);
	// 541 points with a limit of 400: k = 2, 271 kept
	points.resize(541);
	EXPECT_EQ(hslam::matching::everyKthPoint(points, 400).size(), 271u);
}
