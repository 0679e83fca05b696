/* hslam tests: the layers of the subsumption controller (thesis 4.2,
 * eq. 33-36, figures 61-63) on hand-built range profiles. */
#include <gtest/gtest.h>
#include <hslam/nav/CSubsumptionController.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

using namespace hslam::nav;

namespace
{
constexpr double kDeg = M_PI / 180.0;

/** Profile with a straight wall at distance d (m) ahead of the robot. */
CPolarProfile wallAhead(double d, double maxRange = 5.0)
{
	CPolarProfile p(2 * kDeg, maxRange);
	for (double a = -89 * kDeg; a < 89 * kDeg; a += 0.5 * kDeg) p.addPoint(a, std::min(maxRange, d / std::cos(a)));
	return p;
}
}  // namespace

TEST(TargetSeekingLayer, Eq33SpeedAndBearing)
{
	CTargetSeekingLayer layer;
	const auto out = layer.evaluate(mrpt::math::TPose2D(0, 0, M_PI / 2), {0.3, 0.3});
	const double d_mm = std::hypot(300.0, 300.0);
	EXPECT_NEAR(out.v_mps, 0.3 * d_mm / (d_mm + 300.0), 1e-12);  // eq. 33
	EXPECT_NEAR(out.bearing_rad, -M_PI / 4, 1e-12);  // target to the right of a robot facing +y
	EXPECT_FALSE(out.reached);
	EXPECT_TRUE(layer.evaluate(mrpt::math::TPose2D(0, 0, 0), {0.1, 0.1}).reached);  // 141 mm < 200 mm
}

TEST(VelocityControlLayer, Eq34FromRingRanges)
{
	std::array<TVirtualSonar, 8> ring;
	double f = 0;
	for (size_t i = 0; i < 8; ++i)
	{
		ring[i] = {kPioneerSonarAngles_deg[i] * kDeg, 1.0 + 0.5 * i};
		f += (1000.0 + 500.0 * i) * std::cos(ring[i].angle_rad);
	}
	EXPECT_NEAR(CVelocityControlLayer().evaluate(ring), 0.034 * f * 1e-3, 1e-12);
	// Nothing in range: f = 5000 * sum cos = 24 950 mm -> 848 mm/s (the thesis's
	// 14 400 mm / 490 mm/s matches no sonar geometry; docs/nav.md).
	for (auto& s : ring) s.range_m = 5.0;
	EXPECT_NEAR(CVelocityControlLayer().evaluate(ring), 0.848, 0.002);
}

TEST(ForwardTurningLayer, WeightsOfEq35And36)
{
	EXPECT_NEAR(farRangeWeight(3000), 0.5, 1e-12);
	EXPECT_LT(farRangeWeight(1500), 0.001);
	EXPECT_GT(farRangeWeight(4500), 0.999);
	EXPECT_NEAR(sideAvoidanceWeight(400), (160 - 20) / 160.0, 1e-12);
	EXPECT_GT(sideAvoidanceWeight(5000), 0.5);  // never negative up to the 5 m sonar range
}

TEST(ForwardTurningLayer, BacksOffUntil35DegOr150mm)
{
	CForwardTurningLayer layer;
	const auto wall = wallAhead(0.4);
	auto out = layer.update(wall, {0, 0, 0}, 0.0);
	ASSERT_TRUE(out.escaping);
	EXPECT_LT(out.v_mps, 0);
	EXPECT_NE(out.w_rad_s, 0);
	EXPECT_TRUE(layer.update(wall, {-0.05, 0, 20 * kDeg}, 0.5).escaping);
	EXPECT_FALSE(layer.update(wall, {-0.05, 0, 36 * kDeg}, 1.0).escaping) << "rotated 36 deg";
	ASSERT_TRUE(layer.update(wall, {0, 0, 0}, 2.0).escaping);
	EXPECT_FALSE(layer.update(wall, {-0.16, 0, 0}, 3.0).escaping) << "backed 160 mm";
	EXPECT_FALSE(layer.update(wallAhead(0.8), {0, 0, 0}, 4.0).escaping) << "800 mm ahead: no trigger";
}

TEST(CornerTrapDetector, InsideCornerYesOpenSideNo)
{
	CPolarProfile corner(2 * kDeg, 5.0);
	for (double a = -90 * kDeg; a <= 90 * kDeg; a += kDeg)  // walls at x = 0.6 and y = +-0.6
		corner.addPoint(a, std::min({0.6 / std::max(1e-6, std::cos(a)), 0.6 / std::max(1e-6, std::abs(std::sin(a))), 5.0}));
	CCornerTrapDetector det;
	EXPECT_TRUE(det.looksLikeCorner(corner));
	EXPECT_FALSE(det.update(corner));
	EXPECT_FALSE(det.update(corner));
	EXPECT_TRUE(det.update(corner)) << "confirmed after 3 steps";
	EXPECT_FALSE(det.looksLikeCorner(wallAhead(0.6))) << "a flat wall is no corner";
}

TEST(SectorSelectingLayer, PicksTheGapNearestTheTarget)
{
	// Wall 1 m ahead with a 1.2 m gap to the left (y in [0.4, 1.6]).
	CPolarProfile p(1 * kDeg, 5.0);
	for (double y = -5; y <= 5; y += 0.02)
		if (y < 0.4 || y > 1.6) p.addPoint(std::atan2(y, 1.0), std::hypot(1.0, y));
	// Sectors only (use_gaps = false): the clear direction nearest the target, into the gap.
	TSectorSelectingOptions sectorsOnly;
	sectorsOnly.use_gaps = false;
	const auto choice = CSectorSelectingLayer(sectorsOnly).evaluate(p, 0.0, 4.0);  // target ahead, behind the wall
	EXPECT_FALSE(choice.target_clear);
	ASSERT_TRUE(choice.left_rad.has_value());
	EXPECT_GT(choice.chosen_rad, 15 * kDeg);
	EXPECT_LT(choice.chosen_rad, 60 * kDeg);
	// With gaps: the gap (middle (1, 1), 1.2 m wide) is the way to the target; the
	// robot, 1 m off its axis, first heads for the axis 1 m before the gap: (0, 1), 90 deg.
	const auto withGaps = CSectorSelectingLayer().evaluate(p, 0.0, 4.0);
	ASSERT_GE(withGaps.chosen_gap, 0);
	EXPECT_NEAR(withGaps.gaps[withGaps.chosen_gap].width_m, 1.2, 0.05);
	EXPECT_NEAR(withGaps.chosen_rad, 90 * kDeg, 3 * kDeg);
}

TEST(SideAvoidanceLayer, TurnsAwayFromTheCrowdedSide)
{
	std::array<TVirtualSonar, 8> ring;
	for (size_t i = 0; i < 8; ++i) ring[i] = {kPioneerSonarAngles_deg[i] * kDeg, 5.0};
	ring[0].range_m = ring[1].range_m = 0.8;  // obstacle on the left
	const auto out = CSideAvoidanceLayer().evaluate(ring, 0.3);
	EXPECT_FALSE(out.subsume);
	EXPECT_LT(out.w_rad_s, 0) << "obstacle left: turn right";
	ring[0].range_m = 0.3;
	const auto near = CSideAvoidanceLayer().evaluate(ring, 0.3);
	EXPECT_TRUE(near.subsume);
	EXPECT_LT(near.w_rad_s, 0);
}

TEST(TargetSequence, ParsesAndRejectsBadInput)
{
	const auto t = parseTargetList("1 2; -0.5 3.5;", "targets");
	ASSERT_EQ(t.size(), 2u);
	EXPECT_DOUBLE_EQ(t[1].x, -0.5);
	EXPECT_THROW(parseTargetList("1 2; 3", "targets"), std::runtime_error);
	EXPECT_THROW(parseTargetList("1 x", "targets"), std::runtime_error);
}

TEST(SubsumptionController, StopsAtTheLastTarget)
{
	CSubsumptionController c;
	c.setTargets({{1.0, 0.0}});
	auto cmd = c.step({0, 0, 0}, nullptr, nullptr, 0.0);
	EXPECT_EQ(cmd.state, ENavState::navigating);
	EXPECT_GT(cmd.v_mps, 0.1);
	cmd = c.step({0.9, 0.0, 0}, nullptr, nullptr, 1.0);
	EXPECT_EQ(cmd.state, ENavState::target_reached);
	EXPECT_EQ(cmd.v_mps, 0.0);
	EXPECT_EQ(cmd.w_rad_s, 0.0);
	EXPECT_EQ(cmd.targets_reached, 1u);
}

TEST(SubsumptionOptions, ShippedIniLoadsWithEveryKeyAtItsDefault)
{
	const mrpt::config::CConfigFile ini(std::string(HSLAM_SOURCE_DIR) + "/config_ini/nav-subsumption.ini");
	const auto loaded = TSubsumptionOptions::load(ini);
	mrpt::config::CConfigFileMemory a, b;
	loaded.save(a);
	TSubsumptionOptions().save(b);
	EXPECT_EQ(a.getContent(), b.getContent());
	for (const auto& section : TSubsumptionOptions::sections()) EXPECT_TRUE(ini.sectionExists(section)) << section;
}

namespace
{
/** Laser scan (LMS200: 181 beams over 180 deg, at the robot centre) of a wall at
 * x = 1 m with an opening for y in [0.2, 1.1] (a 0.9 m door seen at an angle),
 * and a far wall at x = 4.5 m behind it. */
mrpt::obs::CObservation2DRangeScan doorScan()
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 8.0f;
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		const double a = -0.5 * M_PI + i * kDeg;
		double r = 8.0;
		if (std::cos(a) > 1e-6)
		{
			const double y = std::tan(a);
			r = (y >= 0.2 && y <= 1.1) ? 4.5 / std::cos(a) : 1.0 / std::cos(a);
		}
		scan.setScanRange(i, static_cast<float>(std::min(r, 7.9)));
		scan.setScanRangeValidity(i, r < 7.9);
	}
	return scan;
}

/** One front sonar at the robot centre facing yaw_deg, echo at range_m (30 deg cone). */
mrpt::obs::CObservationRange oneSonar(double yaw_deg, double range_m)
{
	mrpt::obs::CObservationRange s;
	s.maxSensorDistance = 5.0f;
	s.sensorConeApperture = static_cast<float>(30 * kDeg);
	mrpt::obs::CObservationRange::TMeasurement m;
	m.sensorPose = mrpt::math::TPose3D(0, 0, 0.2, yaw_deg * kDeg, 0, 0);
	m.sensedDistance = static_cast<float>(range_m);
	s.sensedData.push_back(m);
	return s;
}
}  // namespace

TEST(RangeFusion, AnEchoTheLaserExplainsDoesNotHideTheDoorBesideIt)
{
	// Sonar at 10 deg (cone -5..25 deg) echoing off the wall next to the door at
	// ~1.0 m: the laser sees that wall in the cone, so the echo is explained and
	// the door's bins (11..25 deg) keep the laser's 4.5 m. Filling the cone
	// (drop_explained_sonar = false, the old fusion) put 1.0 m over them.
	const auto scan = doorScan();
	const auto sonar = oneSonar(10, 1.02);
	const auto fused = CRangeFusion().fuse(&scan, &sonar);
	TRangeFusionOptions fillAll;
	fillAll.drop_explained_sonar = false;
	const auto filled = CRangeFusion(fillAll).fuse(&scan, &sonar);
	EXPECT_GT(fused.minRange(14 * kDeg, 24 * kDeg), 4.0) << "the door stays open";
	EXPECT_LT(filled.minRange(14 * kDeg, 24 * kDeg), 1.1) << "the cone filled over the door";
	EXPECT_NEAR(fused.minRange(-4 * kDeg, 4 * kDeg), 1.0, 0.02) << "the wall is still there (laser)";
}

TEST(RangeFusion, AnEchoNearerThanAllTheLaserSawFillsItsCone)
{
	// Sonar at 30 deg (cone 15..45 deg, all inside the door) echoing at 0.8 m
	// while the laser sees 4.5 m+ there: something the laser cannot see (glass,
	// a low object, thesis 4.9.1): the cone is filled.
	const auto scan = doorScan();
	const auto sonar = oneSonar(30, 0.8);
	const auto fused = CRangeFusion().fuse(&scan, &sonar);
	EXPECT_NEAR(fused.minRange(20 * kDeg, 40 * kDeg), 0.8, 0.01);
}

TEST(PolarProfile, CorridorFreeDistancesMatchOneQueryPerHeading)
{
	const auto scan = doorScan();
	const auto sonar = oneSonar(-40, 0.7);
	const auto p = CRangeFusion().fuse(&scan, &sonar);
	std::vector<double> all;
	for (const double step_deg : {4.0, 7.0})  // 7 deg: the grid does not close on itself
	{
		const int n = static_cast<int>(180 / step_deg);
		p.corridorFreeDistances(step_deg * kDeg, n, 0.34, all);
		ASSERT_EQ(all.size(), size_t(2 * n + 1));
		for (int k = -n; k <= n; ++k)
			EXPECT_NEAR(all[k + n], p.corridorFreeDistance(k * step_deg * kDeg, 0.34), 1e-9) << k * step_deg << " deg";
	}
}

TEST(SectorSelectingLayer, FindsADoorSeenAtAnAngleAndLinesUpWithItsAxisFirst)
{
	const auto scan = doorScan();
	const auto p = CRangeFusion().fuse(&scan, nullptr);
	CSectorSelectingLayer layer;
	// Target through the door (3, 0.65): its bearing is blocked by the near jamb.
	const double tx = 3.0, ty = 0.65;
	const auto choice = layer.evaluate(p, std::atan2(ty, tx), std::hypot(tx, ty));
	EXPECT_FALSE(choice.target_clear);
	ASSERT_GE(choice.chosen_gap, 0) << "the door is the candidate with the shortest path to the target";
	const auto& g = choice.gaps[choice.chosen_gap];
	EXPECT_NEAR(g.width_m, 0.9, 0.05);
	EXPECT_NEAR(0.5 * (g.ex + g.qx), 1.0, 0.05);
	EXPECT_NEAR(0.5 * (g.ey + g.qy), 0.65, 0.05);
	// 0.65 m off the door's axis: aim at the axis 0.65 m before the door,
	// (0.35, 0.65), i.e. 62 deg, well left of the door's middle (33 deg).
	EXPECT_NEAR(choice.chosen_rad, std::atan2(0.65, 0.35), 3 * kDeg);
	// On the axis (the door's middle straight ahead): through it.
	EXPECT_NEAR(layer.gapHeading(1.0, -0.45, 1.0, 0.45), 0.0, 1e-9);
	// Within half the slack ((0.9 - 2 x 0.34) / 4 = 0.055 m) of the axis: along it, not at the middle.
	EXPECT_NEAR(layer.gapHeading(1.0, -0.40, 1.0, 0.50), std::atan2(0.05, 0.6), 1e-6);
}

TEST(SubsumptionController, TurnsInPlaceTowardsATargetBehind)
{
	// Nothing sensed, target 120 deg to the left: the heading is beyond the
	// 70 deg of the forward turning layer, so no forward motion (the rule used
	// to read the rate clipped at 60 deg/s, i.e. 40 deg, and never fired).
	CSubsumptionController c;
	c.setTargets({{-1.0, 1.732}});
	const auto cmd = c.step({0, 0, 0}, nullptr, nullptr, 0.0);
	EXPECT_EQ(cmd.v_mps, 0.0);
	EXPECT_GT(cmd.w_rad_s, 0.9);
	EXPECT_TRUE(cmd.turn_in_place);
}
