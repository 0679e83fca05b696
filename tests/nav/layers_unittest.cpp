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
	CSectorSelectingLayer layer;
	const auto choice = layer.evaluate(p, 0.0, 4.0);  // target straight ahead, behind the wall
	EXPECT_FALSE(choice.target_clear);
	ASSERT_TRUE(choice.left_rad.has_value());
	EXPECT_GT(choice.chosen_rad, 15 * kDeg);
	EXPECT_LT(choice.chosen_rad, 60 * kDeg);
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
