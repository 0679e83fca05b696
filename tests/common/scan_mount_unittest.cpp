/* TScanMount: a scanner's beams on the robot's plane from its full 3D
 * sensorPose (a laser mounted upside down sweeps the other way). */
#include <gtest/gtest.h>
#include <hslam/common/range_data.h>
#include <mrpt/system/datetime.h>

#include <cmath>

using hslam::common::makeRangeData;
using hslam::common::scanMount;
using mrpt::poses::CPose3D;

namespace
{
constexpr double kDeg = M_PI / 180;

/** A 3-beam scan (-90, 0, +90 deg, right to left) with ranges 1, 2, 3 m. */
mrpt::obs::CObservation2DRangeScan threeBeams(const CPose3D& sensorPose)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 10;
	scan.resizeScan(3);
	for (size_t i = 0; i < 3; ++i) scan.setScanRange(i, static_cast<float>(i + 1)), scan.setScanRangeValidity(i, true);
	scan.sensorPose = sensorPose;
	scan.timestamp = mrpt::Clock::now();
	return scan;
}
}  // namespace

TEST(ScanMount, LevelMountKeepsTheTwoDimensionalPose)
{
	const auto m = scanMount(CPose3D(0.2, -0.1, 0.3, 30 * kDeg, 0, 0));
	EXPECT_FALSE(m.upside_down);
	EXPECT_DOUBLE_EQ(m.yaw_rad, 30 * kDeg);
	EXPECT_DOUBLE_EQ(m.bearing(10 * kDeg), 40 * kDeg);
	EXPECT_DOUBLE_EQ(m.x_m, 0.2);
	EXPECT_DOUBLE_EQ(m.y_m, -0.1);
}

TEST(ScanMount, UpsideDownMountSweepsTheOtherWayHoweverItsAnglesAreSpelled)
{
	// roll 180 deg, and the same rotation written as yaw + 180, pitch 180
	for (const CPose3D& p : {CPose3D(0, 0, 0.3, 30 * kDeg, 0, M_PI), CPose3D(0, 0, 0.3, 210 * kDeg, M_PI, 0)})
	{
		const auto m = scanMount(p);
		EXPECT_TRUE(m.upside_down);
		EXPECT_NEAR(std::remainder(m.bearing(10 * kDeg) - 20 * kDeg, 2 * M_PI), 0, 1e-12);
	}
}

TEST(ScanMount, RangeDataOfAnUpsideDownLaserIsTheMirroredScan)
{
	// The beam at scan angle -90 deg (range 1 m) of a laser upside down
	// looks to the robot's left, +90 deg (range 3 m) to its right.
	const auto level = makeRangeData(threeBeams(CPose3D(0.1, 0, 0.3, 0, 0, 0)));
	const auto flipped = makeRangeData(threeBeams(CPose3D(0.1, 0, 0.3, 0, 0, M_PI)));
	ASSERT_EQ(level.points.size(), 3u);
	ASSERT_EQ(flipped.points.size(), 3u);
	EXPECT_NEAR(level.points.xy[0].y, -1.0, 1e-6);  // right
	EXPECT_NEAR(flipped.points.xy[0].y, 1.0, 1e-6);  // left
	EXPECT_NEAR(flipped.points.xy[2].y, -3.0, 1e-6);  // the aperture is a float
	EXPECT_NEAR(flipped.points.xy[1].x, 2.1, 1e-6);
	EXPECT_NEAR(flipped.bearing_rad[0], 90 * kDeg, 1e-6);
	const auto end = flipped.alongBeam(2, 3.0);  // the same geometry along a beam
	EXPECT_NEAR(end.x, flipped.points.xy[2].x, 1e-12);
	EXPECT_NEAR(end.y, flipped.points.xy[2].y, 1e-12);
}

TEST(RobotFootprint, ReturnsInsideTheOutlineAreMarkedInvalid)
{
	const hslam::common::TRobotFootprint p3dx{0.21, 0.301, 0.2125};
	auto scan = threeBeams(CPose3D(0.1, 0, 0.3, 0, 0, 0));
	EXPECT_FALSE(hslam::common::hasReturnsInside(scan, p3dx));  // 1, 2, 3 m away
	scan.setScanRange(0, 0.15f);  // right, 0.15 m: (0.1, -0.15) is inside
	scan.setScanRange(1, 0.12f);  // ahead, 0.12 m: x = 0.22 is past the front (0.21)
	EXPECT_TRUE(hslam::common::hasReturnsInside(scan, p3dx));
	EXPECT_EQ(hslam::common::invalidateReturnsInside(scan, p3dx), 1u);
	EXPECT_FALSE(scan.getScanRangeValidity(0));
	EXPECT_TRUE(scan.getScanRangeValidity(1));
	EXPECT_EQ(hslam::common::invalidateReturnsInside(scan, {}), 0u);  // no outline: keep all
}
