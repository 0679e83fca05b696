/* Tests of the walking people: speed, gait (stance/swing), occlusion of laser beams. */
#include <gtest/gtest.h>
#include <hslam/sim/CLaserSimulator.h>
#include <hslam/sim/CWalkingPerson.h>

#include <cmath>
#include <set>

using namespace hslam::sim;

namespace
{
TPersonSpec straightWalker(double speed)
{
	TPersonSpec p;
	p.id = 4;
	p.speed_mps = speed;
	p.leg_radius_m = 0.06;
	p.step_length_m = 0.6;
	p.loop = false;
	p.waypoints = {{0, 0}, {50, 0}};
	return p;
}
}  // namespace

TEST(SimPeople, BodyMovesAtTheSetSpeed)
{
	const CWalkingPerson p(straightWalker(1.2));
	const auto a = p.stateAt(3.0), b = p.stateAt(13.0);
	EXPECT_NEAR(std::hypot(b.body.x - a.body.x, b.body.y - a.body.y) / 10.0, 1.2, 1e-9);
	// The legs' mean is the body, and over a whole gait cycle they also move at the set speed.
	for (double t : {0.0, 1.1, 2.37, 7.9})
	{
		const auto s = p.stateAt(t);
		EXPECT_NEAR(0.5 * (s.legs[0].x + s.legs[1].x), s.body.x, 1e-9);
		EXPECT_NEAR(std::abs(s.legs[0].y - s.legs[1].y), 0.2, 1e-9);  // two hip half-widths
	}
	const double cycle = 2 * 0.6 / 1.2;
	EXPECT_NEAR(p.stateAt(4.0 + cycle).legs[0].x - p.stateAt(4.0).legs[0].x, 1.2 * cycle, 1e-9);
}

TEST(SimPeople, LegsAlternateStanceAndSwing)
{
	const CWalkingPerson p(straightWalker(1.0));
	const double dt = 0.01;
	int switches = 0;
	int stanceBefore = p.stateAt(0.05).stance[0] ? 0 : 1;
	for (double t = 0.05; t < 6.0; t += dt)
	{
		const auto s0 = p.stateAt(t), s1 = p.stateAt(t + dt);
		ASSERT_NE(s0.stance[0], s0.stance[1]) << "exactly one leg on the ground at t=" << t;
		const int stance = s0.stance[0] ? 0 : 1;
		if (stance != stanceBefore) ++switches;
		stanceBefore = stance;
		if (s1.stance[stance] == s0.stance[stance] && s1.stance[stance])
		{
			EXPECT_NEAR(s1.legs[stance].x, s0.legs[stance].x, 1e-12);  // planted foot does not move
			const int swing = 1 - stance;
			EXPECT_NEAR((s1.legs[swing].x - s0.legs[swing].x) / dt, 2.0, 1e-6);  // swing at 2v
		}
	}
	EXPECT_NEAR(switches, 6.0 / 0.6, 1.0);  // one switch per step
}

TEST(SimPeople, LegsOccludeLaserBeamsAndAreLabelled)
{
	CWorld w;
	w.addSegment(TSegment{{5, -10}, {5, 10}, {}});
	TPersonSpec spec = straightWalker(1.0);
	spec.waypoints = {{2.5, -3}, {2.5, 3}};  // walks across in front of the laser
	const CWalkingPerson person(spec);
	w.setDynamicCircles(person.legCirclesAt(3.0));  // body at (2.5, 0)
	TLaserOptions o;
	o.noise_std_m = 0;
	o.range_resolution_m = 0;
	CLaserSimulator laser(o);
	std::mt19937_64 rng(1);
	mrpt::obs::CObservation2DRangeScan scan;
	std::vector<TObjectTag> tags;
	laser.simulate(w, mrpt::math::TPose2D{0, 0, 0}, rng, scan, &tags);
	int legBeams = 0;
	std::set<int> legsSeen;
	for (size_t i = 0; i < tags.size(); ++i)
	{
		if (tags[i].kind != EObjectKind::person_leg) continue;
		++legBeams;
		legsSeen.insert(tags[i].part);
		EXPECT_EQ(tags[i].group, 4);
		EXPECT_LT(scan.getScanRange(i), 2.7);  // in front of the wall at ~5 m
		EXPECT_GT(scan.getScanRange(i), 2.2);
	}
	// Two 12 cm legs at 2.5 m subtend ~2.7 deg each: 2-3 beams per leg at 1 deg.
	EXPECT_GE(legBeams, 4);
	EXPECT_LE(legBeams, 7);
	EXPECT_EQ(legsSeen.size(), 2u);
	// Without people all those beams reach the wall.
	w.setDynamicCircles({});
	mrpt::obs::CObservation2DRangeScan empty;
	laser.simulate(w, mrpt::math::TPose2D{0, 0, 0}, rng, empty);
	EXPECT_NEAR(empty.getScanRange(90), 5.0 - 0.021, 1e-5);
}
