#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/testing/temp_dir.h>

#include <cmath>

using namespace hslam::common;

TEST(TumTrajectory, WriteReadRoundTripIncludingNegativeAngles)
{
	hslam::testing::CTempDir dir;
	TTrajectory2D traj;
	for (int i = 0; i < 10; ++i)
		traj.push_back({1000.0 + 0.1 * i, {0.5 * i, -0.25 * i, -3.0 + 0.6 * i}});
	writeTumFile(dir.file("t.tum"), traj);
	const auto back = readTumFile(dir.file("t.tum"));
	ASSERT_EQ(back.size(), traj.size());
	for (size_t i = 0; i < traj.size(); ++i)
	{
		EXPECT_NEAR(back[i].t_s, traj[i].t_s, 1e-6);
		EXPECT_NEAR(back[i].pose.x, traj[i].pose.x, 1e-6);
		EXPECT_NEAR(back[i].pose.y, traj[i].pose.y, 1e-6);
		EXPECT_NEAR(std::remainder(back[i].pose.phi - traj[i].pose.phi, 2 * M_PI), 0.0, 1e-8);
	}
}

TEST(TumTrajectory, MalformedLinesNameFileAndLine)
{
	try
	{
		parseTum("# header\n1 0 0 0 0 0 0 1\n2 0 0 0 0 0 x 1\n", "traj.tum");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("traj.tum:3"), std::string::npos) << e.what();
	}
	EXPECT_THROW(parseTum("1 0 0 0 0 0 1\n", "a"), std::runtime_error);  // 7 fields
	EXPECT_THROW(parseTum("1 0 0 0 0 0 0.5 0.5\n", "a"), std::runtime_error);  // not unit
	EXPECT_THROW(readTumFile("/nonexistent.tum"), std::runtime_error);
}
