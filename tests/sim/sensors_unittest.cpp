/* Tests of the laser and sonar models: walls at known distances, grazing
 * sonars (no echo / long multipath echo), corner retro-reflection, the MRPT
 * observation layout. */
#include <gtest/gtest.h>
#include <hslam/sim/CLaserSimulator.h>
#include <hslam/sim/CSonarSimulator.h>

#include <cmath>

using namespace hslam::sim;
using mrpt::math::TPose2D;

namespace
{
CWorld wallAtX(double x)
{
	CWorld w;
	w.addSegment(TSegment{{x, -20}, {x, 20}, {}});
	return w;
}
TLaserOptions exactLaser()
{
	TLaserOptions o;
	o.noise_std_m = 0;
	o.range_resolution_m = 0;
	return o;
}
}  // namespace

TEST(SimLaser, Lms200MeasuresAWallAtItsDistance)
{
	const CWorld w = wallAtX(3.0);
	CLaserSimulator laser(exactLaser());
	ASSERT_EQ(laser.beamCount(), 181u);
	std::mt19937_64 rng(1);
	mrpt::obs::CObservation2DRangeScan scan;
	laser.simulate(w, TPose2D{0, 0, 0}, rng, scan);
	EXPECT_EQ(scan.getScanSize(), 181u);
	EXPECT_FLOAT_EQ(scan.aperture, static_cast<float>(M_PI));
	EXPECT_TRUE(scan.rightToLeft);
	EXPECT_FLOAT_EQ(scan.maxRange, 8.0f);
	const double d = 3.0 - 0.021;  // sensor 21 mm ahead of the centre of rotation
	EXPECT_NEAR(scan.getScanRange(90), d, 1e-5);
	EXPECT_NEAR(scan.getScanRange(90 + 30), d / std::cos(M_PI / 6), 1e-5);  // beam at +30 deg
	EXPECT_NEAR(scan.getScanRange(90 - 60), d / std::cos(M_PI / 3), 1e-5);
	// Beams at +-80 deg exceed 8 m: invalid.
	EXPECT_FALSE(scan.getScanRangeValidity(10));
	EXPECT_TRUE(scan.getScanRangeValidity(90));
}

TEST(SimLaser, NoiseHasTheConfiguredSigmaAndPresetsTheirGeometry)
{
	TLaserOptions o;
	o.noise_std_m = 0.02;
	o.range_resolution_m = 0;
	CLaserSimulator laser(o);
	const CWorld w = wallAtX(2.0);
	std::mt19937_64 rng(3);
	double sum = 0, sum2 = 0;
	int n = 0;
	for (int k = 0; k < 50; ++k)
	{
		mrpt::obs::CObservation2DRangeScan scan;
		laser.simulate(w, TPose2D{0, 0, 0}, rng, scan);
		for (int i = 80; i <= 100; ++i)
		{
			const double expected = (2.0 - 0.021) / std::cos(laser.beamAngle(i));
			const double e = scan.getScanRange(i) - expected;
			sum += e;
			sum2 += e * e;
			++n;
		}
	}
	EXPECT_NEAR(sum / n, 0.0, 0.003);
	EXPECT_NEAR(std::sqrt(sum2 / n), 0.02, 0.002);

	TLaserOptions lms100;
	lms100.preset = "lms100";
	CLaserSimulator l100(lms100);
	EXPECT_EQ(l100.beamCount(), 541u);
	EXPECT_NEAR(l100.fov_rad(), 1.5 * M_PI, 1e-12);
	EXPECT_DOUBLE_EQ(l100.maxRange_m(), 20.0);
}

TEST(SimLaser, ArtefactsComeAtTheirRatesAndOnlyWhenAsked)
{
	// A wall at 3 m with a box in front of it (1.5 m, beams 80-100): two
	// edges where neighbouring beams jump by 1.5 m.
	CWorld w = wallAtX(3.0);
	w.addSegment(TSegment{{1.5, -0.25}, {1.5, 0.25}, {}});
	std::mt19937_64 rngA(5), rngB(5);
	mrpt::obs::CObservation2DRangeScan plain, again;
	CLaserSimulator(exactLaser()).simulate(w, TPose2D{0, 0, 0}, rngA, plain);
	CLaserSimulator(exactLaser()).simulate(w, TPose2D{0, 0, 0}, rngB, again);
	EXPECT_EQ(rngA(), rngB());  // all off: nothing drawn, a sample stays what it was
	TLaserOptions o = exactLaser();
	o.dropout_probability = 0.1;
	o.spurious_probability = 0.05;
	o.mixed_pixel_probability = 1.0;
	CLaserSimulator laser(o);
	std::mt19937_64 rng(7);
	int valid = 0, lost = 0, shorter = 0, between = 0, scans = 400;
	for (int k = 0; k < scans; ++k)
	{
		mrpt::obs::CObservation2DRangeScan scan;
		laser.simulate(w, TPose2D{0, 0, 0}, rng, scan);
		for (size_t i = 0; i < scan.getScanSize(); ++i)
		{
			if (!plain.getScanRangeValidity(i)) continue;
			const double truth = plain.getScanRange(i), r = scan.getScanRange(i);
			const bool edge = i > 0 && i + 1 < scan.getScanSize() &&
							  (std::abs(plain.getScanRange(i - 1) - truth) > 0.3 ||
							   std::abs(plain.getScanRange(i + 1) - truth) > 0.3);
			if (edge && truth < 2.0 && scan.getScanRangeValidity(i) && r > truth + 1e-6 && r < 3.0) ++between;
			if (edge) continue;
			++valid;
			if (!scan.getScanRangeValidity(i)) ++lost;
			else if (r < truth - 1e-6) ++shorter;
		}
	}
	EXPECT_NEAR(static_cast<double>(lost) / valid, 0.1, 0.01);
	EXPECT_NEAR(static_cast<double>(shorter) / valid, 0.9 * 0.05, 0.01);  // of those not lost
	// both edge beams of the box (on the nearer surface) are mixed in every
	// scan, unless lost or made spurious after
	EXPECT_GT(between, static_cast<int>(2 * scans * 0.8));
}

TEST(SimSonar, RingHasTheP3dxGeometryAndObservationLayout)
{
	TSonarOptions o;
	o.noise_std_m = 0;
	CSonarSimulator sonar(o);
	ASSERT_EQ(sonar.ring().size(), 8u);
	const CWorld w = wallAtX(2.0);
	std::mt19937_64 rng(1);
	mrpt::obs::CObservationRange obs;
	sonar.simulate(w, TPose2D{0, 0, 0}, rng, obs);
	ASSERT_EQ(obs.sensedData.size(), 8u);
	EXPECT_FLOAT_EQ(obs.maxSensorDistance, 5.0f);
	EXPECT_NEAR(obs.sensorConeApperture, 30.0 * M_PI / 180.0, 1e-6);
	EXPECT_EQ(obs.sensedData[3].sensorID, 3);
	EXPECT_NEAR(obs.sensedData[3].sensorPose.x, 0.166, 1e-9);
	EXPECT_NEAR(obs.sensedData[3].sensorPose.y, 0.027, 1e-9);
	EXPECT_NEAR(obs.sensedData[3].sensorPose.yaw, 10.0 * M_PI / 180.0, 1e-9);
	EXPECT_NEAR(obs.sensedData[0].sensorPose.yaw, M_PI / 2, 1e-9);
	// Sonars 3 and 4 (+-10 deg) see the wall; their cones include the perpendicular.
	EXPECT_NEAR(obs.sensedData[3].sensedDistance, 2.0 - 0.166, 1e-4);
	EXPECT_NEAR(obs.sensedData[4].sensedDistance, 2.0 - 0.166, 1e-4);
	// Sonar 0 looks along the wall direction: max range (no echo).
	EXPECT_FLOAT_EQ(obs.sensedData[0].sensedDistance, 5.0f);
}

TEST(SimSonar, RearRingSeesBehind)
{
	TSonarOptions o;
	o.noise_std_m = 0;
	o.ring = "all16";
	CSonarSimulator sonar(o);
	ASSERT_EQ(sonar.ring().size(), 16u);
	const CWorld w = wallAtX(-2.0);  // wall behind the robot
	std::mt19937_64 rng(1);
	mrpt::obs::CObservationRange obs;
	sonar.simulate(w, TPose2D{0, 0, 0}, rng, obs);
	ASSERT_EQ(obs.sensedData.size(), 16u);
	EXPECT_FLOAT_EQ(obs.sensedData[3].sensedDistance, 5.0f);  // front: nothing
	EXPECT_NEAR(obs.sensedData[11].sensedDistance, 2.0 - 0.255, 1e-4);  // rear, heading -170 deg
}

TEST(SimSonar, SonarPointingAtAWallMeasuresItsDistance)
{
	TSonarOptions o;
	o.noise_std_m = 0;
	CSonarSimulator sonar(o);
	const CWorld w = wallAtX(3.0);
	// Robot turned so that sonar 2 (heading 30 deg) faces the wall perpendicularly.
	const TPose2D robot{0, 0, -M_PI / 6};
	const auto& m = sonar.ring()[2];
	const double sx = std::cos(robot.phi) * m.x_m - std::sin(robot.phi) * m.y_m;
	std::mt19937_64 rng(1);
	mrpt::obs::CObservationRange obs;
	std::vector<TSonarEcho> echoes;
	sonar.simulate(w, robot, rng, obs, &echoes);
	EXPECT_NEAR(obs.sensedData[2].sensedDistance, 3.0 - sx, 1e-4);
	EXPECT_EQ(echoes[2].bounces, 0);
}

TEST(SimSonar, GrazingWallGivesNoEchoOrALongMultipathEcho)
{
	// Wall through (2, 0) at 30 deg to the sonar axis: every ray of the 30 deg
	// cone meets it at 45-75 deg incidence, beyond the 25 deg limit.
	const double a = M_PI / 6;
	CWorld w;
	w.addSegment(TSegment{{2 - 10 * std::cos(a), -10 * std::sin(a)}, {2 + 10 * std::cos(a), 10 * std::sin(a)}, {}});
	TSonarOptions o;
	o.noise_std_m = 0;
	o.specular_mode = "none";
	const TPose2D sensor{0, 0, 0};
	const TSonarEcho none = CSonarSimulator(o).echo(w, sensor);
	EXPECT_FALSE(none.echo);
	EXPECT_DOUBLE_EQ(none.range_m, 5.0);
	// Multipath with nothing for the mirrored ray to hit: still no echo.
	o.specular_mode = "multipath";
	EXPECT_FALSE(CSonarSimulator(o).echo(w, sensor).echo);
	// A second wall across the mirrored direction (60 deg) 2 m further on
	// returns a long echo: half of 2 + 2 + |hit2 - sensor| = 3.73 m, the wall is 2 m away.
	const double rx = 0.5, ry = std::sqrt(3.0) / 2;  // mirrored direction
	const double hx = 2 + 2 * rx, hy = 2 * ry;  // second hit
	w.addSegment(TSegment{{hx - 3 * ry, hy + 3 * rx}, {hx + 3 * ry, hy - 3 * rx}, {}});
	const TSonarEcho multi = CSonarSimulator(o).echo(w, sensor);
	ASSERT_TRUE(multi.echo);
	EXPECT_EQ(multi.bounces, 1);
	EXPECT_GT(multi.range_m, 3.0);
	EXPECT_NEAR(multi.range_m, 0.5 * (4.0 + std::hypot(hx, hy)), 0.15);
}

TEST(SimSonar, ConcaveCornerIsARetroReflector)
{
	// A 90 deg corner at (3, 0) seen along its bisector: both walls at 45 deg
	// incidence (no direct echo), but the double bounce comes back.
	CWorld w;
	w.addSegment(TSegment{{3, 0}, {0, 3}, {}});
	w.addSegment(TSegment{{3, 0}, {0, -3}, {}});
	TSonarOptions o;
	o.noise_std_m = 0;
	o.cone_rad = 10.0 * M_PI / 180.0;  // narrow cone: only near-bisector rays
	const TSonarEcho e = CSonarSimulator(o).echo(w, TPose2D{0, 0, 0});
	ASSERT_TRUE(e.echo);
	EXPECT_EQ(e.bounces, 1);
	EXPECT_NEAR(e.range_m, 3.0, 0.05);
	o.specular_mode = "none";
	EXPECT_FALSE(CSonarSimulator(o).echo(w, TPose2D{0, 0, 0}).echo);
}
