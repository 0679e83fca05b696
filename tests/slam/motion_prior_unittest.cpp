/* CMotionPrior: speeds are judged over min_interval_s at least and never
 * exceed what the robot can do (the intel failure: two scans 20 ms apart made
 * an ordinary increment a "jump" and a matched turn a 29 rad/s velocity). */
#include <gtest/gtest.h>
#include <hslam/slam/CMotionPrior.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using hslam::slam::CMotionPrior;
using hslam::slam::TMotionPrior;
using hslam::slam::TOdometryIncrement;
using mrpt::poses::CPose2D;

namespace
{
constexpr double kDeg = M_PI / 180;

TOdometryIncrement odometry(double x, double y, double phi)
{
	TOdometryIncrement i;
	i.delta = CPose2D(x, y, phi);
	return i;
}
}  // namespace

TEST(MotionPrior, AnOrdinaryIncrementTwentyMillisecondsLaterIsNoJump)
{
	CMotionPrior prior;
	prior.prior(odometry(0, 0, 0), 10.0);
	// 5 cm and 8 deg: 400 deg/s over 20 ms (over max_turn_rate), ordinary over 0.25 s.
	const TMotionPrior p = prior.prior(odometry(0.05, 0, 8 * kDeg), 10.02);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
	// A real jump (2 m in 20 ms, more than max_speed_mps x 0.25 s) still is one.
	const TMotionPrior jump = prior.prior(odometry(2.0, 0, 0), 10.04);
	EXPECT_EQ(jump.reason, "jump");
}

TEST(MotionPrior, VelocityIsMeasuredOverTheMinimumInterval)
{
	CMotionPrior prior;
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.observePose(CPose2D(0.5, 0, 0), 1.0);
	prior.observePose(CPose2D(0.5, 0, 0.58), 1.02);  // a 33 deg correction 20 ms later
	// Over the last 1.02 s (the newest estimate at least 0.25 s old is t = 0):
	// 0.58 rad / 1.02 s, not 0.58 rad / 0.02 s = 29 rad/s.
	EXPECT_NEAR(prior.velocity().z(), 0.58 / 1.02, 1e-9);
	EXPECT_NEAR(prior.velocity().x(), 0.5 / 1.02, 1e-9);
}

TEST(MotionPrior, ARestartIsNoMotion)
{
	// The robot drives at 0.6 m/s; the filter is restarted 1.1 m ahead (where
	// refused matches put it). Measured across the restart, the velocity was
	// (1.1 + 0.12) / 0.4 = 3 m/s (the robot's limit); after restarted() it is
	// measured from the restart on: 0.12 m / 0.2 s.
	const auto drive = [](CMotionPrior& prior, bool restart)
	{
		for (int k = 0; k <= 5; ++k) prior.observePose(CPose2D(0.12 * k, 0, 0), 0.2 * k);  // 0.6 m/s
		if (restart) prior.restarted();
		prior.observePose(CPose2D(0.6 + 1.1, 0, 0), 1.2);
		prior.observePose(CPose2D(0.6 + 1.1 + 0.12, 0, 0), 1.4);
		return prior.velocity().x();
	};
	CMotionPrior across, restarted;
	EXPECT_GT(drive(across, false), 2.5);
	EXPECT_NEAR(drive(restarted, true), 0.6, 1e-9);
}

TEST(MotionPrior, VelocityIsKnownOnceMeasuredAndUnknownAfterARestart)
{
	// unconstrained_axis_after_gap leaves a corridor's axis to this velocity
	// only once it was measured: at a log's first scan, or just after a
	// restart, it is zero because nothing was measured, not because the
	// robot stands.
	CMotionPrior prior;
	EXPECT_FALSE(prior.velocityKnown());
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	EXPECT_FALSE(prior.velocityKnown());  // one pose: no interval yet
	prior.observePose(CPose2D(0.5, 0, 0), 1.0);
	EXPECT_TRUE(prior.velocityKnown());
	EXPECT_NEAR(prior.velocity().x(), 0.5, 1e-9);
	prior.restarted();
	EXPECT_FALSE(prior.velocityKnown());
	prior.observePose(CPose2D(2.0, 0, 0), 2.0);
	EXPECT_FALSE(prior.velocityKnown());
	prior.observePose(CPose2D(2.4, 0, 0), 3.0);
	EXPECT_TRUE(prior.velocityKnown());
}

TEST(MotionPrior, VelocityNeverExceedsTheRobotsLimits)
{
	CMotionPrior::TOptions o;
	o.max_speed_mps = 1.5;
	o.max_turn_rate_rad_s = 90 * kDeg;
	CMotionPrior prior(o);
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.observePose(CPose2D(3, 4, 2.0), 0.5);  // 10 m/s, 4 rad/s
	EXPECT_NEAR(prior.velocity().head<2>().norm(), 1.5, 1e-9);
	EXPECT_NEAR(prior.velocity().x() / prior.velocity().y(), 3.0 / 4.0, 1e-9);  // direction kept
	EXPECT_NEAR(prior.velocity().z(), 90 * kDeg, 1e-9);
	// The constant-velocity prior over the next second extrapolates at most that.
	TOdometryIncrement gap;
	gap.known = false;
	prior.prior(gap, 0.5);
	const TMotionPrior p = prior.prior(gap, 1.5);
	EXPECT_EQ(p.reason, "gap");
	EXPECT_NEAR(p.delta.norm(), 1.5, 1e-9);
	EXPECT_NEAR(p.delta.phi(), 90 * kDeg, 1e-9);
}

TEST(MotionPrior, UnknownMotionBeforeTheFirstOdometryIsNoStall)
{
	// aces cut at entry 6: no odometry reading before the second scan, which
	// the scans saw turn 44 deg; the next interval has odometry again.
	CMotionPrior prior;
	TOdometryIncrement unknown;
	unknown.known = false;
	prior.prior(unknown, 22.74);
	prior.observePose(CPose2D(0, 0, 0), 22.74);
	EXPECT_EQ(prior.prior(unknown, 23.86).reason, "gap");
	prior.observePose(CPose2D(0.14, -0.11, -43.7 * kDeg), 23.86);
	// the unknown interval is not "odometry read zero while the robot turned"
	const TMotionPrior p = prior.prior(odometry(1.02, -0.05, 6.5 * kDeg), 25.41);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
}

TEST(MotionPrior, StallEvidenceOlderThanTheWindowIsForgotten)
{
	CMotionPrior prior;  // disagreement_window_s = 3
	prior.prior(odometry(0.001, 0, 0), 0.0);
	prior.observePose(CPose2D(0, 0, 0), 0.0);
	prior.prior(odometry(0.001, 0, 0), 1.0);
	prior.observePose(CPose2D(0.5, 0, 0), 1.0);  // the scans moved 0.5 m, odometry 1 mm
	EXPECT_EQ(prior.prior(odometry(0.001, 0, 0), 2.0).reason, "stalled");  // within the window
	prior.observePose(CPose2D(1.0, 0, 0), 2.0);
	// the next scan comes 8 s later: the disagreement at 1-2 s is outside
	// the window ending now, and odometry reports ordinary motion
	const TMotionPrior p = prior.prior(odometry(0.5, 0, 0.1), 10.0);
	EXPECT_EQ(p.source, TMotionPrior::ESource::odometry);
	EXPECT_EQ(p.reason, "");
}

TEST(MotionPrior, MatchesAcceptedFarOutsideThePredictionCountAsRefused)
{
	// Laser-only sample cut at entry 14, the robot driving at 0.6 m/s while
	// the readings creep: against a 2 mm prediction a well-constrained match
	// 0.12 m ahead was accepted (NIS 23, inside gate_nis = 50) and moved the
	// estimate 2 mm; the next two were rejected (NIS 238, 571).
	CMotionPrior prior;  // contradicting_nis = 16.27, rejected_matches_for_stall = 3
	const Eigen::Matrix3d wellConstrained = Eigen::Vector3d(0.03 * 0.03, 0.02 * 0.02, 0.01).asDiagonal();
	double t = 1.0;
	prior.prior(odometry(0.001, 0, 0), t);
	prior.observePose(CPose2D(0, 0, 0), t);
	EXPECT_FALSE(prior.contradictedMatchSeed(t).has_value());
	const double measured[] = {0.120, 0.468, 0.836};
	const double nis[] = {23.2, 237.5, 570.9};
	const bool accepted[] = {true, false, false};
	for (int k = 0; k < 3; ++k)
	{
		t += 0.6;
		EXPECT_NE(prior.prior(odometry(0.001, 0, 0), t).reason, "stalled") << k;
		prior.observeMatch(CPose2D(measured[k], 0, 0), wellConstrained, accepted[k], nis[k], t);
		prior.observePose(CPose2D(0.002 * (k + 1), 0, 0), t);
	}
	// three refused in a row: stalled, and the velocity is the matches' own
	EXPECT_EQ(prior.prior(odometry(0.001, 0, 0), t + 0.2).reason, "stalled");
	EXPECT_NEAR(prior.velocity().x(), (0.836 - 0.468) / 0.6, 1e-9);
	// the seed for the next match: the last refused match moved on by it
	const auto seed = prior.contradictedMatchSeed(t + 0.2);
	ASSERT_TRUE(seed.has_value());
	EXPECT_NEAR(seed->x(), 0.836 + 0.2 * (0.836 - 0.468) / 0.6, 1e-9);
	// with the threshold off, the first (accepted) match resets the count
	CMotionPrior::TOptions o;
	o.contradicting_nis = 0;
	CMotionPrior old(o);
	t = 1.0;
	old.prior(odometry(0.001, 0, 0), t);
	old.observePose(CPose2D(0, 0, 0), t);
	for (int k = 0; k < 3; ++k)
	{
		t += 0.6;
		old.prior(odometry(0.001, 0, 0), t);
		old.observeMatch(CPose2D(measured[k], 0, 0), wellConstrained, accepted[k], nis[k], t);
		old.observePose(CPose2D(0.002 * (k + 1), 0, 0), t);
	}
	EXPECT_NE(old.prior(odometry(0.001, 0, 0), t + 0.2).reason, "stalled");
}

TEST(MotionPrior, MatchesContradictingReadingsThatMoveAreNoStall)
{
	// csail with noisy odometry, draw 4, t = 363-365 s: steps of about 1 m,
	// a scan a second, the readings' heading 20-25 deg off; three
	// well-constrained matches accepted at NIS 19, 17 and 36. The readings
	// showed the motion (1 m of the matched 1 m): noise, not a stall.
	const auto run = [](bool needsCreeping) {
		CMotionPrior::TOptions o;
		o.stall_needs_creeping = needsCreeping;
		CMotionPrior prior(o);
		const Eigen::Matrix3d wellConstrained = Eigen::Vector3d(0.03 * 0.03, 0.02 * 0.02, 0.01).asDiagonal();
		double t = 362.0;
		prior.prior(odometry(1.0, 0, 0.1), t);
		prior.observeMatch(CPose2D(0, 0, 0), wellConstrained, true, 2.0, t);
		prior.observePose(CPose2D(0, 0, 0), t);
		const double nis[] = {19.3, 16.8, 35.8};
		CPose2D matched;
		for (int k = 0; k < 3; ++k)
		{
			t += 1.0;
			prior.prior(odometry(1.0, 0.0, 0.4), t);  // the readings: 1 m and 23 deg of turn
			matched = matched + CPose2D(1.0, 0.0, -0.3);  // the matches: 1 m and -17 deg
			prior.observeMatch(matched, wellConstrained, true, nis[k], t);
			prior.observePose(matched, t);
		}
		return prior.prior(odometry(1.0, 0, 0.4), t + 1.0).reason;
	};
	EXPECT_NE(run(true), "stalled");
	EXPECT_EQ(run(false), "stalled");  // the rule as it was: a constant velocity took over
}

TEST(MotionPrior, NoRefusedSeedOnceAMatchAgreesOrTheWindowHasPassed)
{
	CMotionPrior prior;
	const Eigen::Matrix3d wellConstrained = Eigen::Vector3d(0.03 * 0.03, 0.02 * 0.02, 0.01).asDiagonal();
	prior.prior(odometry(0.001, 0, 0), 1.0);
	prior.observeMatch(CPose2D(0.5, 0, 0), wellConstrained, false, 200, 1.0);
	EXPECT_TRUE(prior.contradictedMatchSeed(1.5).has_value());
	EXPECT_FALSE(prior.contradictedMatchSeed(1.0 + 3.1).has_value());  // disagreement_window_s = 3
	prior.observeMatch(CPose2D(0.01, 0, 0), wellConstrained, true, 1.0, 1.6);  // agrees
	EXPECT_FALSE(prior.contradictedMatchSeed(1.7).has_value());
	// a corridor match (unconstrained along the axis) says nothing either way
	const Eigen::Matrix3d corridor = Eigen::Vector3d(5.0 * 5.0, 0.02 * 0.02, 0.01).asDiagonal();
	prior.observeMatch(CPose2D(2.0, 0, 0), corridor, false, 300, 1.8);
	EXPECT_FALSE(prior.contradictedMatchSeed(1.9).has_value());
}

namespace
{
/** Drives at 0.8 m/s with scans every 0.2 s up to t = 2 s, then the readings
 * drop to exact zeros for `zeros` scans while the estimates follow them (the
 * filter believed the zeros); returns the last prior. */
TMotionPrior zerosAfterDriving(CMotionPrior& prior, double speed_mps, int zeros)
{
	const double dt = 0.2;
	double x = 0, t = 0;
	for (int k = 0; k <= 10; ++k, t += dt, x += speed_mps * dt)
	{
		prior.prior(odometry(k == 0 ? 0.0 : speed_mps * dt, 0, 0), t);
		prior.observePose(CPose2D(x, 0, 0), t);
	}
	x -= speed_mps * dt;
	TMotionPrior p;
	for (int k = 0; k < zeros; ++k, t += dt)
	{
		p = prior.prior(odometry(0, 0, 0), t);
		prior.observePose(CPose2D(x, 0, 0), t);
	}
	return p;
}
}  // namespace

TEST(MotionPrior, ReadingsFrozenAtSpeedKeepTheVelocityMeasuredBefore)
{
	// At 0.8 m/s a scan interval of 0.2 s ends at 0.4 m/s at most with
	// max_decel_mps2 = 2: exact zeros from 0.8 m/s are a fault, not a stop.
	// The first two zeros' estimates stood still (frozen_min_scans = 3); the
	// frozen prior keeps 0.8 m/s, measured before them, and catches up on
	// them: from the estimate at t = 2.0 s, the last before the zeros, to
	// where 0.8 m/s carries it by t = 2.6 s.
	CMotionPrior atSpeed;
	const TMotionPrior frozen = zerosAfterDriving(atSpeed, 0.8, 3);
	EXPECT_EQ(frozen.reason, "frozen");
	EXPECT_TRUE(frozen.velocity_measured);
	EXPECT_NEAR(frozen.delta.x(), 0.8 * 0.6, 1e-6);
	// Through the fault the velocity is held: the estimates are its own
	// extrapolations (here they lag), and they do not re-measure it.
	atSpeed.observePose(CPose2D(1.6 + 0.3, 0, 0), 2.6);
	const TMotionPrior next = atSpeed.prior(odometry(0, 0, 0), 2.8);
	EXPECT_NEAR(next.delta.x(), 0.8 * 0.2, 1e-6);
	// Without the rule the velocity is the estimates' of the last 0.25 s at
	// least: the zeros' standstill, and nothing says it was measured.
	CMotionPrior::TOptions off;
	off.max_decel_mps2 = 0;
	CMotionPrior without(off);
	const TMotionPrior stood = zerosAfterDriving(without, 0.8, 3);
	EXPECT_EQ(stood.reason, "frozen");
	EXPECT_FALSE(stood.velocity_measured);
	EXPECT_LT(stood.delta.x(), 0.5 * 0.8 * 0.2);
	// From 0.3 m/s a stop within one interval is possible: an ordinary stop.
	CMotionPrior slow;
	const TMotionPrior stop = zerosAfterDriving(slow, 0.3, 3);
	EXPECT_EQ(stop.reason, "frozen");
	EXPECT_FALSE(stop.velocity_measured);
	// Odometry that moves again is trusted again.
	EXPECT_FALSE(atSpeed.prior(odometry(0.16, 0, 0), 10.0).velocity_measured);
}

TEST(MotionPrior, ReadingsLostAtSpeedKeepAMeasuredVelocity)
{
	CMotionPrior prior;
	zerosAfterDriving(prior, 0.8, 0);
	TOdometryIncrement lost;
	lost.known = false;
	const TMotionPrior gap = prior.prior(lost, 2.2);  // one interval after the last reading
	EXPECT_EQ(gap.reason, "gap");
	EXPECT_TRUE(gap.velocity_measured);
	EXPECT_NEAR(gap.delta.x(), 0.8 * 0.2, 0.01);
	CMotionPrior slow;
	zerosAfterDriving(slow, 0.3, 0);
	EXPECT_FALSE(slow.prior(lost, 2.2).velocity_measured);
}

TEST(MotionPrior, AStallEndsOnlyWhenOdometryAgreesAgain)
{
	// Readings creeping at 1 % while the scans move the estimate 0.12 m per
	// 0.2 s: stalled. Then matching stops seeing the motion (a corridor whose
	// walls hold no feature along the axis, the laser-only building seen by
	// an 8 m scanner) and the estimate stands still for 4 s: the old rule
	// ended the stall there and trusted the creeping readings again, so the
	// estimate stayed put while the robot drove on.
	const auto run = [](bool endsOnAgreement)
	{
		CMotionPrior::TOptions o;
		o.stall_ends_on_agreement = endsOnAgreement;
		CMotionPrior prior(o);
		std::vector<std::string> reasons;
		double t = 0, x = 0;
		const auto scan = [&](double odometry_m, double estimateStep_m)
		{
			t += 0.2;
			reasons.push_back(prior.prior(odometry(odometry_m, 0, 0), t).reason);
			x += estimateStep_m;
			prior.observePose(CPose2D(x, 0, 0), t);
		};
		for (int k = 0; k < 10; ++k) scan(0.0012, 0.12);  // 2 s driving, readings at 1 %
		for (int k = 0; k < 20; ++k) scan(0.0012, 0.0);  // 4 s the estimate stands still
		for (int k = 0; k < 15; ++k) scan(0.12, 0.12);  // 3 s readings and estimate agree
		return reasons;
	};
	const auto sticky = run(true), old = run(false);
	ASSERT_EQ(sticky.size(), 45u);
	EXPECT_EQ(sticky[9], "stalled");  // 0.96 m in the window, readings 1 %
	EXPECT_EQ(old[9], "stalled");
	// 3.2 s after the estimate stopped, no motion is left in the 3 s window
	EXPECT_EQ(sticky[26], "stalled");
	EXPECT_EQ(old[26], "");
	for (int k = 10; k < 30; ++k) EXPECT_EQ(sticky[static_cast<size_t>(k)], "stalled") << k;
	// once the readings report the motion the estimate makes, the stall ends
	// (within the 3 s window: as soon as the window's motion is 0.3 m with
	// the readings' share above disagreement_ratio)
	EXPECT_EQ(sticky.back(), "");
	const auto firstTrusted = std::find(sticky.begin() + 30, sticky.end(), "") - sticky.begin();
	EXPECT_LE(firstTrusted, 34);
}

TEST(MotionPrior, WhileStalledTheSpeedComesFromMatchesASecondApart)
{
	// Readings creeping at 1 % while the robot drives at 0.8 m/s: stalled.
	// From 1.8 s the estimate lags 0.39 m (a bare stretch of corridor left
	// the axis to the prior); at 2.4 s a well-constrained match puts it
	// where the robot is. Measured from the estimates over 0.4 s, that
	// correction is 1.8 m/s (simulated floor laps: 1.7 m/s, and the prior
	// then ran 20 m ahead); between matches at least a second apart it is
	// the robot's 0.8 m/s, whatever the lag.
	const auto run = [](double baseline_s)
	{
		CMotionPrior::TOptions o;
		o.stalled_velocity_baseline_s = baseline_s;
		CMotionPrior prior(o);
		const Eigen::Matrix3d constrained = Eigen::Vector3d(0.02 * 0.02, 0.02 * 0.02, 1e-4).asDiagonal();
		std::vector<double> speeds;
		for (int k = 1; k <= 18; ++k)
		{
			const double t = 0.2 * k, truth = 0.8 * t;
			const double estimate = k >= 9 && k <= 11 ? truth - 0.39 : truth;
			prior.prior(odometry(0.0016, 0, 0), t);  // 1 % of 0.16 m
			if (k >= 12) prior.observeMatch(CPose2D(truth, 0, 0), constrained, true, 0.0, t);
			prior.observePose(CPose2D(estimate, 0, 0), t);
			speeds.push_back(prior.velocity().x());
		}
		EXPECT_EQ(prior.prior(odometry(0.0016, 0, 0), 3.8).reason, "stalled");
		return speeds;
	};
	const auto baseline = run(1.0), fromEstimates = run(0);
	EXPECT_GT(fromEstimates[11], 1.5);  // at 2.4 s: 1.78 m/s
	for (size_t k = 11; k < baseline.size(); ++k) EXPECT_LT(baseline[k], 1.0) << "at " << 0.2 * (k + 1) << " s";
	EXPECT_NEAR(baseline.back(), 0.8, 1e-9);  // matches from 2.4 s to 3.6 s
}

TEST(MotionPrior, ATurnAloneIsNoStallWhileTheReadingsShowTheDistance)
{
	// csail with curving, biased or noisy odometry, scans 25-27 (1 s apart):
	// the readings turned -5, 7 and 1 deg where the scans turned -46, 10 and
	// 17 over the same 0.4, 0.9 and 0.7 m. The readings are alive (their
	// distance is right); only their turn lags. The old rule called it a
	// stall at scan 28, whose recovery put the scan 3.2 m and 118 deg off.
	// Readings whose heading stopped changing, and a robot turning in place
	// on readings that do not turn, still make one.
	const auto reasonAtLastScan = [](double turnOnlyRatio, double distanceScale, double turnScale)
	{
		CMotionPrior::TOptions o;
		o.turn_only_disagreement_ratio = turnOnlyRatio;
		CMotionPrior prior(o);
		const double odometry_m[] = {0.43, 0.92, 0.71, 0.49}, odometry_deg[] = {-5.4, 6.7, 1.0, -20.0};
		const double estimate_m[] = {0.38, 0.94, 0.74}, estimate_deg[] = {-45.8, 10.2, 16.8};
		CPose2D pose;
		prior.observePose(pose, 24.0);
		std::string reason;
		for (int k = 0; k < 4; ++k)
		{
			const double t = 25.0 + k;
			reason = prior.prior(odometry(distanceScale * odometry_m[k], 0, turnScale * odometry_deg[k] * kDeg), t).reason;
			if (k < 3) pose = pose + CPose2D(distanceScale * estimate_m[k], 0, estimate_deg[k] * kDeg);
			prior.observePose(pose, t);
		}
		return reason;
	};
	EXPECT_EQ(reasonAtLastScan(0.1, 1.0, 1.0), "");
	EXPECT_EQ(reasonAtLastScan(0.25, 1.0, 1.0), "stalled");  // the old rule: disagreement_ratio
	// a heading that stopped changing (readings turn 1 % of those turns)
	EXPECT_EQ(reasonAtLastScan(0.1, 1.0, 0.01 * 73 / 13), "stalled");
	// the same turns made in place (0.1 % of the distance: below
	// disagreement_min_motion_m, so the distance cannot refute the stall)
	EXPECT_EQ(reasonAtLastScan(0.1, 0.001, 1.0), "stalled");
}

TEST(MotionPrior, ZerosAfterMotionAreUnknownMotionUntilTheyCountAsFrozen)
{
	// A scan a second at 0.8 m/s, then readings that stop changing: a stop
	// within the interval is possible at max_decel_mps2 (2 m/s^2), so the
	// zeros are no fault "at speed", but they may be motion: a
	// constant-velocity prior carrying the velocity before them, until
	// frozen_min_scans. A robot that crept (1 cm/s) before them has stopped.
	const auto reasons = [](double speed_mps, bool unknown)
	{
		CMotionPrior::TOptions o;
		o.zeros_after_motion_unknown = unknown;
		CMotionPrior prior(o);
		std::vector<std::string> out;
		std::vector<double> deltas;
		double x = 0;
		for (int k = 1; k <= 8; ++k)
		{
			const double t = k;
			const TMotionPrior p = prior.prior(odometry(k <= 4 ? speed_mps : 0.0, 0, 0), t);
			out.push_back(p.reason), deltas.push_back(p.delta.x());
			x += k <= 4 ? speed_mps : p.delta.x();
			prior.observePose(CPose2D(x, 0, 0), t);
		}
		return std::make_pair(out, deltas);
	};
	const auto [moving, movingDeltas] = reasons(0.8, true);
	EXPECT_EQ(moving[3], "");
	EXPECT_EQ(moving[4], "zeros");  // the first zero
	EXPECT_NEAR(movingDeltas[4], 0.8, 1e-9);
	EXPECT_EQ(moving[5], "zeros");
	EXPECT_EQ(moving[6], "frozen");  // frozen_min_scans = 3
	EXPECT_EQ(reasons(0.8, false).first[4], "");  // followed as a stop
	EXPECT_EQ(reasons(0.01, true).first[4], "");  // crept: 1 cm in the interval, below creep_min_motion_m
}
