/* Tests of the P3-DX kinematics and the UMBmark odometry errors (thesis 4.1, eq. 26-28). */
#include <gtest/gtest.h>
#include <hslam/sim/CDiffDriveRobot.h>
#include <hslam/sim/CPathFollower.h>
#include <hslam/sim/COdometryFault.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

using namespace hslam::sim;

namespace
{
TDiffDriveOptions noLimits()
{
	TDiffDriveOptions o;
	o.max_accel_mps2 = 0;
	o.max_rot_accel_rad_s2 = 0;
	return o;
}

void drive(CDiffDriveRobot& robot, double v, double w, double seconds, std::mt19937_64& rng, double dt = 0.01)
{
	const int n = static_cast<int>(std::lround(seconds / dt));
	for (int k = 0; k < n; ++k) robot.step(v, w, dt, rng);
}
}  // namespace

TEST(SimKinematics, StraightCommandGivesStraightGroundTruth)
{
	std::mt19937_64 rng(1);
	CDiffDriveRobot robot(noLimits(), mrpt::math::TPose2D{1, 2, M_PI / 6});
	drive(robot, 0.5, 0.0, 10.0, rng);
	const auto& p = robot.truePose();
	EXPECT_NEAR(p.x, 1 + 5.0 * std::cos(M_PI / 6), 1e-9);
	EXPECT_NEAR(p.y, 2 + 5.0 * std::sin(M_PI / 6), 1e-9);
	EXPECT_NEAR(p.phi, M_PI / 6, 1e-12);
	EXPECT_NEAR(robot.odometryPose().x, p.x, 1e-9);
	EXPECT_NEAR(robot.leftWheelTravel_m(), 5.0, 1e-9);
}

TEST(SimKinematics, WheelRatioErrorGivesCurvatureOfEq26And27)
{
	TDiffDriveOptions o = noLimits();
	o.ed_wheel_diameter_ratio = 1.01;  // right wheel 1 % larger -> curves left
	o.eb_wheelbase_ratio = 1.02;
	std::mt19937_64 rng(1);
	CDiffDriveRobot robot(o, mrpt::math::TPose2D{0, 0, 0});
	drive(robot, 0.4, 0.0, 10.0, rng);  // 4 m straight command
	// Odometry believes the straight line.
	EXPECT_NEAR(robot.odometryPose().y, 0.0, 1e-12);
	EXPECT_NEAR(robot.odometryPose().x, 4.0, 1e-9);
	// Truth: a circle of radius R = (b_actual/2)(Ed+1)/(Ed-1) (eq. 27 solved for R).
	const double R = umbmarkCurvatureRadius(1.01, 0.335 * 1.02);
	EXPECT_NEAR(R, 0.5 * 0.3417 * 2.01 / 0.01, 1e-9);
	const auto& p = robot.truePose();
	const double arc = 4.0;  // the mean wheel diameter is unchanged
	const double beta = arc / R;
	EXPECT_NEAR(p.phi, beta, 1e-9);
	// Eq. 26: the chord L travelled and the heading change beta satisfy R = L / (2 sin(beta/2)).
	const double chord = std::hypot(p.x, p.y);
	EXPECT_NEAR(chord / (2.0 * std::sin(0.5 * p.phi)), R, 1e-6);
	// Eq. 27 back from R gives the ratio d = Ed.
	const double b = 0.335 * 1.02;
	EXPECT_NEAR((R + b / 2) / (R - b / 2), 1.01, 1e-12);
	EXPECT_GT(p.y, 0.0);  // turned left
}

TEST(SimKinematics, WheelbaseErrorScalesTurns)
{
	TDiffDriveOptions o = noLimits();
	o.eb_wheelbase_ratio = 1.05;
	std::mt19937_64 rng(1);
	CDiffDriveRobot robot(o, mrpt::math::TPose2D{0, 0, 0});
	drive(robot, 0.0, M_PI / 20, 10.0, rng);  // commanded 90 deg in place
	EXPECT_NEAR(robot.odometryPose().phi, M_PI / 2, 1e-9);
	EXPECT_NEAR(robot.truePose().phi, (M_PI / 2) / 1.05, 1e-9);
}

TEST(SimKinematics, RandomErrorsGrowWithDistanceAndAreSeeded)
{
	TDiffDriveOptions o = noLimits();
	o.wheel_noise_m_per_sqrt_m = 0.01;
	auto finalHeadingStd = [&](double metres) {
		double sum2 = 0;
		for (int run = 0; run < 200; ++run)
		{
			std::mt19937_64 rng(100 + run);
			CDiffDriveRobot r(o, mrpt::math::TPose2D{0, 0, 0});
			drive(r, 0.5, 0.0, metres / 0.5, rng, 0.05);
			sum2 += r.truePose().phi * r.truePose().phi;
		}
		return std::sqrt(sum2 / 200);
	};
	// Heading std after d metres: sqrt(2) k sqrt(d) / b (two independent wheels).
	const double s4 = finalHeadingStd(4.0), s16 = finalHeadingStd(16.0);
	EXPECT_NEAR(s4, std::sqrt(2.0) * 0.01 * 2.0 / 0.335, 0.2 * s4);
	EXPECT_NEAR(s16 / s4, 2.0, 0.4);
	std::mt19937_64 a(5), b(5);
	CDiffDriveRobot ra(o, {}), rb(o, {});
	drive(ra, 0.5, 0.1, 3.0, a);
	drive(rb, 0.5, 0.1, 3.0, b);
	EXPECT_EQ(ra.truePose().x, rb.truePose().x);
	EXPECT_NE(ra.truePose().x, ra.odometryPose().x);
}

TEST(SimKinematics, PathFollowerDrivesTheSquare)
{
	std::mt19937_64 rng(1);
	CDiffDriveRobot robot(TDiffDriveOptions(), mrpt::math::TPose2D{0, 0, 0});
	CPathFollower follower(TPathFollowerOptions(), {{4, 0}, {4, 4}, {0, 4}, {0, 0}});
	double t = 0;
	while (!follower.finished() && t < 200)
	{
		const auto cmd = follower.command(robot.truePose());
		robot.step(cmd.v_mps, cmd.w_rad_s, 0.01, rng);
		t += 0.01;
	}
	ASSERT_TRUE(follower.finished());
	EXPECT_LT(std::hypot(robot.truePose().x, robot.truePose().y), 0.05);
	EXPECT_GT(t, 16.0 / 0.4);  // at most cruise speed
}

TEST(SimKinematics, ScriptsAndWaypointListsParseWithClearErrors)
{
	const auto pts = parseWaypointList("1 2; 3 4;", "[path] waypoints");
	ASSERT_EQ(pts.size(), 2u);
	EXPECT_DOUBLE_EQ(pts[1].y, 4.0);
	CVelocityScript script(parseVelocityScript("2 0.5 0; 1 0 90", "[path] commands"));
	EXPECT_DOUBLE_EQ(script.duration_s(), 3.0);
	EXPECT_DOUBLE_EQ(script.commandAt(2.5).w_rad_s, M_PI / 2);
	EXPECT_DOUBLE_EQ(script.commandAt(5).v_mps, 0.0);
	try
	{
		parseWaypointList("1 2; 3 x", "[path] waypoints");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("[path] waypoints: item 2"), std::string::npos) << e.what();
	}
	EXPECT_THROW(parseVelocityScript("1 2", "c"), std::runtime_error);
}

TEST(SimOdometryFault, LagReportsThePoseOfFaultLagSecondsEarlier)
{
	// Hand-derived: the encoder moves 0.1 m and 1 deg per 10 ms step; with a
	// 0.305 s lag the reading at step k reports the newest encoder pose at
	// least that old, step k - 31 (the start pose until then); once the
	// window ends, the encoder pose itself.
	hslam::sim::TOdometryFaultOptions o;
	o.fault = "lag";
	o.fault_lag_s = 0.305;
	o.fault_duration_s = 1.0;
	hslam::sim::COdometryFault fault(o, mrpt::math::TPose2D(1, 2, 0));
	auto encoderAt = [](int step) { return mrpt::math::TPose2D(1 + 0.1 * step, 2, mrpt::DEG2RAD(1.0 * step)); };
	for (int step = 0; step <= 50; ++step)
	{
		fault.update(0.01 * step, encoderAt(step));
		const auto reported = fault.reportedPose();
		const int expected = std::max(0, step - 31);
		EXPECT_NEAR(reported.x, encoderAt(expected).x, 1e-9) << "step " << step;
		EXPECT_NEAR(reported.phi, encoderAt(expected).phi, 1e-9) << "step " << step;
	}
	for (int step = 51; step <= 120; ++step) fault.update(0.01 * step, encoderAt(step));
	EXPECT_NEAR(fault.reportedPose().x, encoderAt(120).x, 1e-9);  // after the window: the encoder pose
}
