/* hslam tests: strict CARMEN line parsing (CCarmenLineParser). */
#include <gtest/gtest.h>
#include <hslam/io/CCarmenLineParser.h>

using namespace hslam::io;

namespace
{
TCarmenMessage parseOk(const std::string& line)
{
	const auto m = CCarmenLineParser().parse(line);
	EXPECT_TRUE(m.has_value()) << line;
	return *m;
}

std::string errorOf(const std::string& line)
{
	try
	{
		CCarmenLineParser().parse(line);
	}
	catch (const carmen_format_error& e)
	{
		return e.what();
	}
	ADD_FAILURE() << "no error for: " << line;
	return {};
}
}  // namespace

TEST(CarmenLineParser, Flaser)
{
	const auto m = parseOk("FLASER 3 1.5 2.5 81.91 0.1 0.2 0.3 0.4 0.5 0.6 12.5 host 12.75");
	const auto& laser = std::get<TCarmenLaser>(m);
	EXPECT_EQ(laser.name, "FLASER");
	EXPECT_EQ(laser.role, TCarmenLaserRole::lrFront);
	ASSERT_EQ(laser.ranges_m.size(), 3u);
	EXPECT_DOUBLE_EQ(laser.ranges_m[2], 81.91);
	EXPECT_DOUBLE_EQ(laser.laserPose->phi, 0.3);
	EXPECT_DOUBLE_EQ(laser.robotPose->x, 0.4);
	EXPECT_DOUBLE_EQ(laser.stamp.ipc_s, 12.5);
	EXPECT_EQ(laser.stamp.host, "host");
	EXPECT_DOUBLE_EQ(laser.stamp.logger_s, 12.75);
	EXPECT_FALSE(laser.config.has_value());
	EXPECT_EQ(std::get<TCarmenLaser>(parseOk("RLASER 1 2 0 0 0 0 0 0 1 h 1")).role, TCarmenLaserRole::lrRear);
}

TEST(CarmenLineParser, RobotLaserAndRawLaser)
{
	// type start fov res max acc mode n r.. m rem.. laser(3) robot(3) tv rv fwd side turn ipc host logger
	const auto robot = std::get<TCarmenLaser>(parseOk(
		"ROBOTLASER1 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 2 1.0 2.0 1 77 1 2 0.1 0.9 2 0.1 0.5 0.2 0 0 0 9.5 h 9.6"));
	EXPECT_EQ(robot.role, TCarmenLaserRole::lrFront);
	EXPECT_DOUBLE_EQ(robot.config->startAngle_rad, -1.5708);
	EXPECT_DOUBLE_EQ(robot.config->resolution_rad, 0.0174533);
	EXPECT_EQ(robot.ranges_m.size(), 2u);
	EXPECT_DOUBLE_EQ(robot.laserPose->x, 1.0);
	EXPECT_DOUBLE_EQ(robot.robotPose->x, 0.9);
	EXPECT_DOUBLE_EQ(robot.tv_mps, 0.5);
	EXPECT_DOUBLE_EQ(robot.stamp.logger_s, 9.6);
	EXPECT_EQ(std::get<TCarmenLaser>(parseOk("ROBOTLASER2 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 1 1.0 0 "
											 "1 2 3.1 0.9 2 0.1 0.5 0.2 0 0 0 9.5 h 9.6"))
				  .role,
			  TCarmenLaserRole::lrRear);

	const auto raw = std::get<TCarmenLaser>(
		parseOk("RAWLASER3 0 -1.5708 3.14159 0.0174533 81.9 0.01 0 2 1.0 2.0 0 5.5 h 5.6"));
	EXPECT_EQ(raw.role, TCarmenLaserRole::lrRaw);
	EXPECT_EQ(raw.rawIndex, 3);
	EXPECT_FALSE(raw.laserPose.has_value());
	EXPECT_DOUBLE_EQ(raw.stamp.ipc_s, 5.5);
}

TEST(CarmenLineParser, OdometryParamsAndSkipped)
{
	const auto odo = std::get<TCarmenOdometry>(parseOk("ODOM 0.6 -0.03 -0.35 0.2 0.1 0 33.1 pippo 33.2"));
	EXPECT_DOUBLE_EQ(odo.pose.y, -0.03);
	EXPECT_DOUBLE_EQ(odo.tv_mps, 0.2);
	EXPECT_DOUBLE_EQ(odo.rv_radps, 0.1);
	EXPECT_DOUBLE_EQ(odo.stamp.logger_s, 33.2);

	// csail style "name value ipc host logger" and intel style "name value host ts"
	auto p = std::get<TCarmenParam>(parseOk("PARAM robot_front_laser_max 50 1134863807.659323 b21 1134863807.65932"));
	EXPECT_EQ(p.name, "robot_front_laser_max");
	EXPECT_EQ(p.value, "50");
	EXPECT_EQ(std::get<TCarmenParam>(parseOk("PARAM robot_frontlaser_offset 0.0 nohost 0")).value, "0.0");
	EXPECT_EQ(std::get<TCarmenParam>(parseOk("PARAM robot_use_laser on")).value, "on");

	EXPECT_EQ(std::get<TCarmenSkipped>(parseOk("NEFF 27.6 0 pippo 0")).name, "NEFF");
	EXPECT_EQ(std::get<TCarmenSkipped>(parseOk("# message formats defined: PARAM SYNC")).name, "#");
	EXPECT_EQ(std::get<TCarmenSkipped>(parseOk("ROBOTLASER0 whatever")).name, "ROBOTLASER0");
	EXPECT_FALSE(CCarmenLineParser().parse("   \t ").has_value());
}

TEST(CarmenLineParser, TimestampsMayBeNanButNotGarbage)
{
	const auto laser = std::get<TCarmenLaser>(parseOk("FLASER 1 2 0 0 0 0 0 0 nan h inf"));
	EXPECT_TRUE(std::isnan(laser.stamp.ipc_s));
	EXPECT_NE(errorOf("FLASER 1 2 0 0 0 0 0 0 12s h 1").find("bad timestamp '12s'"), std::string::npos);
}

TEST(CarmenLineParser, MalformedLinesAreRejected)
{
	EXPECT_NE(errorOf("FLASER 3 1.5 2x5 3 0 0 0 0 0 0 1 h 1").find("bad number '2x5' for range 2"), std::string::npos);
	EXPECT_NE(errorOf("FLASER 3.0 1 2 3 0 0 0 0 0 0 1 h 1").find("bad count '3.0'"), std::string::npos);
	EXPECT_NE(errorOf("FLASER -3 1 2 3 0 0 0 0 0 0 1 h 1").find("bad count"), std::string::npos);
	// 4 ranges but 3 declared: one field too many
	EXPECT_NE(errorOf("FLASER 3 1 2 3 4 0 0 0 0 0 0 1 h 1").find("1 unexpected extra field"), std::string::npos);
	// 2 ranges but 3 declared, or a line cut short
	EXPECT_NE(errorOf("FLASER 3 1 2 0 0 0 0 0 0 1 h 1").find("truncated line"), std::string::npos);
	EXPECT_NE(errorOf("FLASER 180 1 2 3").find("truncated line: FLASER declaring 180 beams"), std::string::npos);
	EXPECT_NE(errorOf("ODOM 1 2 3 0 0 0 5 host").find("truncated line"), std::string::npos);
	EXPECT_NE(errorOf("ODOM 1 2 nan 0 0 0 5 host 5").find("bad number 'nan'"), std::string::npos);
	EXPECT_NE(errorOf("PARAM").find("truncated line"), std::string::npos);
	// remission count that does not match
	EXPECT_NE(errorOf("RAWLASER1 0 -1.57 3.14 0.017 81.9 0.01 0 2 1.0 2.0 2 7 5.5 h 5.6").find("remissions"),
			  std::string::npos);
}
