/* hslam tests: CARMEN beam layout and mounting in MRPT terms. */
#include <gtest/gtest.h>
#include <hslam/io/carmen_observations.h>
#include <hslam/io/carmen_scan_geometry.h>

#include "carmen_test_utils.h"

using namespace hslam::io;
using hslam::testing::carmen::beamAngle_deg;

namespace
{
TCarmenLaser flaserWith(size_t beams, TCarmenLaserRole role = TCarmenLaserRole::lrFront)
{
	TCarmenLaser laser;
	laser.name = role == TCarmenLaserRole::lrFront ? "FLASER" : "RLASER";
	laser.role = role;
	laser.ranges_m.assign(beams, 1.0);
	laser.laserPose = laser.robotPose = mrpt::math::TPose2D(0, 0, 0);
	return laser;
}

mrpt::obs::CObservation2DRangeScan::Ptr scanOf(const TCarmenLaser& laser, const TCarmenLaserMounts& mounts = {})
{
	const auto geometry = carmenScanGeometry(laser);
	TCarmenRangeLimits limits;
	limits.maxRange_m = 80;
	return makeCarmenScan(laser, geometry, carmenSensorPose(laser, mounts, geometry), limits, 1.0);
}
}  // namespace

TEST(CarmenScanGeometry, Beams180StartAtMinus90AndEndAt89)
{
	const auto scan = scanOf(flaserWith(180));
	EXPECT_TRUE(scan->rightToLeft);
	EXPECT_NEAR(scan->aperture * 180 / M_PI, 179.0, 1e-4);
	EXPECT_NEAR(scan->sensorPose.yaw() * 180 / M_PI, -0.5, 1e-9);
	EXPECT_NEAR(beamAngle_deg(*scan, 0), -90.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 90), 0.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 179), 89.0, 1e-4);
	EXPECT_FALSE(carmenScanGeometry(flaserWith(180)).warning.has_value());
}

TEST(CarmenScanGeometry, Beams181And361AreCentred)
{
	auto scan = scanOf(flaserWith(181));
	EXPECT_NEAR(scan->sensorPose.yaw(), 0.0, 1e-12);
	EXPECT_NEAR(beamAngle_deg(*scan, 0), -90.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 180), 90.0, 1e-4);
	scan = scanOf(flaserWith(361));
	EXPECT_NEAR(scan->sensorPose.yaw(), 0.0, 1e-12);
	EXPECT_NEAR(beamAngle_deg(*scan, 1) - beamAngle_deg(*scan, 0), 0.5, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 360), 90.0, 1e-4);
	scan = scanOf(flaserWith(360));
	EXPECT_NEAR(beamAngle_deg(*scan, 0), -90.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 359), 89.5, 1e-4);
}

TEST(CarmenScanGeometry, UnusualBeamCountsAreGuessedWithAWarning)
{
	const auto g = carmenScanGeometry(flaserWith(100));
	ASSERT_TRUE(g.warning.has_value());
	EXPECT_NEAR(g.aperture_rad * 180 / M_PI, 99.0, 1e-9);
	EXPECT_NEAR(carmenScanGeometry(flaserWith(541)).aperture_rad * 180 / M_PI, 270.0, 1e-9);
}

TEST(CarmenScanGeometry, RobotLaserUsesItsOwnConfigAndPoses)
{
	TCarmenLaser laser = flaserWith(5);
	laser.name = "ROBOTLASER1";
	laser.config = TCarmenLaserConfig{mrpt::DEG2RAD(-45.0), mrpt::DEG2RAD(90.0), mrpt::DEG2RAD(22.5), 30.0};
	laser.robotPose = mrpt::math::TPose2D(1, 1, M_PI / 2);
	laser.laserPose = mrpt::math::TPose2D(1, 1.2, M_PI / 2);  // 0.2 m in front of the robot
	const auto scan = scanOf(laser);
	EXPECT_NEAR(scan->sensorPose.x(), 0.2, 1e-9);
	EXPECT_NEAR(scan->sensorPose.y(), 0.0, 1e-9);
	EXPECT_NEAR(beamAngle_deg(*scan, 0), -45.0, 1e-4);
	EXPECT_NEAR(beamAngle_deg(*scan, 4), 45.0, 1e-4);
}

TEST(CarmenScanGeometry, MountsFromParamsRearLooksBackwards)
{
	std::map<std::string, TCarmenParamValue> params{{"robot_frontlaser_offset", {"0.12", 3}},
													{"robot_frontlaser_side_offset", {"-0.05", 4}},
													{"robot_rearlaser_offset", {"-0.2", 5}}};
	const auto mounts = carmenLaserMounts(params, "x.log");
	EXPECT_DOUBLE_EQ(mounts.front.x_m, 0.12);
	EXPECT_DOUBLE_EQ(mounts.front.y_m, -0.05);
	EXPECT_DOUBLE_EQ(mounts.rear.yaw_rad, M_PI);
	auto scan = scanOf(flaserWith(181), mounts);
	EXPECT_NEAR(scan->sensorPose.x(), 0.12, 1e-9);
	scan = scanOf(flaserWith(181, TCarmenLaserRole::lrRear), mounts);
	EXPECT_NEAR(scan->sensorPose.x(), -0.2, 1e-9);
	EXPECT_NEAR(std::abs(scan->sensorPose.yaw()), M_PI, 1e-9);

	params["robot_rearlaser_angular_offset"] = {"abc", 7};
	try
	{
		carmenLaserMounts(params, "x.log");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("x.log:7"), std::string::npos) << e.what();
	}
}
