/* Issue 12's failure classes of the front-end, each reproduced by a simulated
 * run with exact ground truth (rawlog_samples/<name>, or generated here by
 * hslam-simulate from config_ini/sim-<name>.ini), and the default estimator's
 * figure on it asserted against dead reckoning on the same run:
 *   laser only      odometry creeps at 1 % of the wheel motion all run;
 *   odometry gap    the readings freeze for 5 s across a corner;
 *   long corridor   200 m of corridor, degenerate along its axis;
 *   open hall       40 x 30 m hall, most walls far away;
 *   people          six people crossing close to the robot.
 * The estimate must never be worse than odometry, and where odometry fails
 * (laser only, gap) matching alone must carry the robot. */
#include <gtest/gtest.h>
#include <hslam/batch/CBatchProcessor.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace hslam;

namespace
{
struct TScores
{
	double ate_m = 0, rpe5_m = 0;  //!< estimate: ATE RMSE, RPE over 5 m (translation RMSE)
	double odometry_ate_m = 0, odometry_rpe5_m = 0;
	double odometry_scale = 1;  //!< [odometry_self_calibration]'s fitted distance scale
	bool odometry_scale_applied = false;
	double odometry_curvature_rad_per_m = 0;  //!< its fitted heading gain per metre (Ed)
	bool odometry_heading_applied = false;
};

double rpe5(const eval::TTrajectoryErrors& e)
{
	for (const auto& r : e.rpe)
		if (r.name == "5m") return r.errors.trans_m.rmse;
	return -1;
}

/** The default pipeline on `folder`/sim.rawlog from entry `firstEntry` on
 * (the run cut there, as rawlog-edit --cut --from-index does), scored against
 * its ground truth. */
/** Changes an entry before the pipeline sees it (a different robot's rawlog). */
using TEntryEdit = std::function<void(io::TRawlogEntry&)>;

TScores runDefault(const std::string& folder, const std::vector<std::string>& overrides = {}, size_t firstEntry = 0,
				   const TEntryEdit& edit = {})
{
	std::vector<std::string> o{"process.laser_label=LASER"};
	o.insert(o.end(), overrides.begin(), overrides.end());
	const auto cfg = common::loadConfigWithOverrides(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini", o);
	slam::CMappingPipeline pipeline(cfg);
	io::CRawlogReader reader(folder + "/sim.rawlog");
	size_t index = 0;
	for (io::TRawlogEntry e; reader.next(e); ++index)
		if (index >= firstEntry)
		{
			if (edit) edit(e);
			pipeline.processEntry(e);
		}
	const auto truth = common::readTumFile(folder + "/ground_truth.tum");
	const auto est = eval::evaluateTrajectory(truth, pipeline.trajectory());
	const auto odo = eval::evaluateTrajectory(truth, pipeline.odometryTrajectory());
	const auto& calibration = pipeline.odometryCalibration().state();
	return {est.ate.position_m.rmse,	  rpe5(est),
			odo.ate.position_m.rmse,		  rpe5(odo),
			calibration.distance_scale,		  calibration.distance_applied,
			calibration.curvature_bias_rad_per_m, calibration.heading_applied};
}

/** Overrides that check a standstill claim like any other timed match. */
const std::vector<std::string> kPointToPointStandstillCheck{"icp.standstill_point_to_line_steps=0",
															"icp.standstill_fit_max_segment_m=0"};

/** The keyframe policy before the twenty-third round: a keyframe wherever the
 * estimate had moved far enough, placed by ICP or not. Several failure
 * classes below were found, and their remedies measured, under it; the
 * rule that only ICP places keyframes contains some of them as well, so
 * their counterfactuals pin the old policy. */
const std::string kAnyKeyframes = "pose_estimation.keyframes_after_icp_only=false";
/** Counterfactuals measured before the wide search after a poor match ([gap_search] after_poor_match)... */
const std::string kNoSlipSearch = "gap_search.after_poor_match=false";
/** ...and before refused matches needed readings that creep to declare a stall ([motion_prior] stall_needs_creeping). */
const std::string kStallOnAnyRefusal = "motion_prior.stall_needs_creeping=false";

std::string shipped(const std::string& name) { return std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/" + name; }

/** Simulates config_ini/sim-<name>.ini into dir (a few seconds). */
std::string simulated(const std::string& name, const hslam::testing::CTempDir& dir, const std::string& extra = "")
{
	const std::string out = dir.file(name);
	EXPECT_EQ(hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-simulate -q -c " + HSLAM_SOURCE_DIR +
								  "/config_ini/sim-" + name + ".ini -o " + out + " " + extra + " >" + out + ".log 2>&1"),
			  0);
	return out;
}

void print(const std::string& name, const TScores& s)
{
	std::cout << name << ": ATE " << s.ate_m << " m (odometry " << s.odometry_ate_m << "), RPE 5 m " << s.rpe5_m
			  << " m (odometry " << s.odometry_rpe5_m << ")\n";
}

/** The default pipeline on `folder` and the same run with one remedy
 * switched off (`off`, a --set override), both printed. */
struct TRemedy
{
	TScores on, off;
};
TRemedy withAndWithout(const std::string& folder, const std::string& off, const std::string& name)
{
	TRemedy r{runDefault(folder), runDefault(folder, {off})};
	print(name + ", default", r.on);
	print(name + ", " + off, r.off);
	return r;
}

/** hslam-simulate overrides for a scanner unlike the LMS200 (rate 0: the world's). */
std::string customLaser(double fov_deg, double resolution_deg, double maxRange_m, double rate_hz = 0)
{
	std::ostringstream o;
	o << "--set laser.preset=custom --set laser.fov_deg=" << fov_deg << " --set laser.resolution_deg=" << resolution_deg
	  << " --set laser.max_range_m=" << maxRange_m;
	if (rate_hz > 0) o << " --set laser.rate_hz=" << rate_hz;
	return o.str();
}

/** hslam-simulate overrides: odometry fault `fault` for 10 s from t = 30 s (stress matrix freeze / drop). */
std::string fault10sAt30(const std::string& fault)
{
	return "--set odometry.fault=" + fault + " --set odometry.fault_start_s=30 --set odometry.fault_duration_s=10";
}

/** `world` scanned at 1 Hz (csail's spacing) with a 10 s odometry `fault`
 * from t = 30 s, run with the default and with the remedy `off`. */
TRemedy faultAtOneHertz(const std::string& world, const std::string& fault, const std::string& off,
						const hslam::testing::CTempDir& dir)
{
	const auto folder = simulated(world, dir, fault10sAt30(fault) + " --set laser.rate_hz=1");
	return withAndWithout(folder, off, world + " at 1 Hz, readings " + fault + " 10 s");
}
}  // namespace

TEST(FrontEndScenarios, LaserOnlyIsTrackedByMatchingAlone)
{
	const TScores s = runDefault(shipped("laser-only"));
	print("laser only", s);
	EXPECT_GT(s.odometry_ate_m, 5.0);  // the class: odometry is useless (9.2 m)
	EXPECT_LT(s.ate_m, 0.2);  // measured 0.099 m (before issue 12: 9.2 m, as odometry)
}

TEST(FrontEndScenarios, LaserOnlyStartedWhileDrivingIsTracked)
{
	// Cut at entry 14 the laser-only run starts with the robot driving along a
	// corridor at 0.55 m/s. The filter trusted the creeping readings' 2 mm
	// prediction, refused the matches that saw the motion and stayed put for
	// 17 s: ATE 1.37 m (24: 1.76 m, 36: 4.19 m). Matches accepted far outside
	// the prediction now count as refused ([motion_prior] contradicting_nis),
	// and ICP is also seeded where the refused matches put the robot
	// ([pose_estimation] seed_refused_matches).
	const TScores s = runDefault(shipped("laser-only"), {}, 14);
	print("laser only, from entry 14", s);
	EXPECT_GT(s.odometry_ate_m, 5.0);
	EXPECT_LT(s.ate_m, 0.2);  // measured 0.117 m
	// From entry 150 three matches were refused and the stall declared, but
	// from the stuck state a wrong ICP result fitted the only keyframe better
	// than the right one from the refused matches' seed (3.13 m): the filter
	// is now restarted where the refused matches put the robot.
	const TScores later = runDefault(shipped("laser-only"), {}, 150);
	print("laser only, from entry 150", later);
	EXPECT_LT(later.ate_m, 0.2);  // measured 0.086 m
	// From entry 50 the seeds end in two basins that fit alike (the stuck
	// state and the moving robot) before any match is refused: the match,
	// widened over both for the filter (competing_basins.h), must still count
	// for the motion prior in its own basin (3.79 m when it counted neither way).
	const TScores widened = runDefault(shipped("laser-only"), {}, 50);
	print("laser only, from entry 50", widened);
	EXPECT_LT(widened.ate_m, 0.2);
	// From entry 200 two matches were refused, then the stuck state's result
	// fitted the only keyframe better than the refused track's and reset
	// the count (1.80 m): a result competing with the refused track's no
	// longer confirms the prediction.
	const TScores track = runDefault(shipped("laser-only"), {}, 200);
	print("laser only, from entry 200", track);
	EXPECT_LT(track.ate_m, 0.2);
	// Without competing basins the standstill check alone now holds this
	// start too (thirteenth round, LaserOnlyStartedMidCorridor... below);
	// without both it fails.
	const TScores trackOff = runDefault(shipped("laser-only"), {"icp.competing_fit_ratio=0"}, 200);
	print("laser only, from entry 200, no competing basins", trackOff);
	EXPECT_LT(trackOff.ate_m, 0.2);  // measured 0.066 m
	std::vector<std::string> neither = kPointToPointStandstillCheck;
	neither.push_back("icp.competing_fit_ratio=0");
	const TScores neitherTrack = runDefault(shipped("laser-only"), neither, 200);
	print("laser only, from entry 200, no competing basins, point-to-point standstill check", neitherTrack);
	EXPECT_GT(neitherTrack.ate_m, 0.5);
	// (the nineteenth and twentieth rounds' remedies hold this start too:
	// the stalled matches' point-to-line check alone 0.062 m, the stall that
	// ends on agreement alone 0.207 m, with keyframes on time 0.101 m, the
	// unconstrained axis left to the prior with the speed measured between
	// matches a second apart 0.219 m; they are switched off here with the
	// older two)
	const TScores old = runDefault(
		shipped("laser-only"),
		{"motion_prior.contradicting_nis=0", "pose_estimation.seed_refused_matches=false",
		 "pose_estimation.stalled_point_to_line=false", "motion_prior.stall_ends_on_agreement=false",
		 "pose_estimation.stalled_keyframe_every_s=0", "pose_estimation.stalled_unconstrained_max_fraction=0",
		 "motion_prior.stalled_velocity_baseline_s=0"},
		14);
	print("laser only, from entry 14, as before", old);
	EXPECT_GT(old.ate_m, 0.5);  // the failure, so this test can fail
}

TEST(FrontEndScenarios, LaserOnlyStartedMidCorridorIsNotHeldAtTheFirstScan)
{
	// Cut at entry 110 (and 2200) the run starts at 0.6 m/s 5 m into a
	// corridor (a corridor whose side walls are bare). Every match was a
	// timed one (odometry claims no motion) against the only keyframe, the
	// first scan: point-to-point ICP and its nearest-point fit favoured zero
	// motion (the scans sample the walls at the same bearings there), and
	// the estimate stayed within 0.14 m of the start while the robot drove
	// 15 m: ATE 3.85 m (2200: 2.95 m). The standstill check is now refined
	// point-to-line and judged by the point-to-segment fit ([icp]
	// standstill_*).
	for (const size_t entry : {110u, 2200u})
	{
		const TScores s = runDefault(shipped("laser-only"), {}, entry);
		print("laser only, from entry " + std::to_string(entry), s);
		EXPECT_LT(s.ate_m, 0.2);  // measured 0.070 m (110), 0.114 m (2200)
	}
	const TScores old = runDefault(shipped("laser-only"), kPointToPointStandstillCheck, 110);
	print("laser only, from entry 110, point-to-point standstill check", old);
	EXPECT_GT(old.ate_m, 1.0);
}

TEST(FrontEndScenarios, OdometryGapIsRecoveredByMatching)
{
	const TScores s = runDefault(shipped("odometry-gap"));
	print("odometry gap", s);
	EXPECT_GT(s.odometry_ate_m, 3.0);  // 6.0 m
	EXPECT_LT(s.ate_m, 0.25);  // measured 0.117 m (before: 5.8 m)
}

TEST(FrontEndScenarios, MissingOdometryReadingsAreRecoveredByMatching)
{
	hslam::testing::CTempDir dir;  // the same run with no readings at all for 5 s (ODOMETRY_GAP)
	const TScores s = runDefault(simulated("odometry-gap", dir, "--set odometry.fault=drop"));
	print("odometry gap (no readings)", s);
	EXPECT_GT(s.odometry_ate_m, 3.0);  // 6.0 m
	EXPECT_LT(s.ate_m, 0.25);  // measured 0.117 m
}

TEST(FrontEndScenarios, ReadingsLostAtSpeedDownACorridorKeepTheVelocity)
{
	// The long corridor with no odometry readings for 10 s from t = 30 s,
	// the robot at 0.8 m/s (stress matrix variant 'drop'). The corridor
	// leaves its axis loose: matching without a prediction pulls the robot
	// back to the last keyframe, and the estimate stood still through the
	// fault. [motion_prior] max_decel_mps2 keeps the velocity measured
	// before; [pose_estimation] unconstrained_axis_after_gap (the next test)
	// alone also fixes it (0.35 m), so both are switched off for the
	// counterfactual.
	hslam::testing::CTempDir dir;
	const auto lost = simulated("long-corridor", dir, fault10sAt30("drop"));
	const TScores kept = runDefault(lost);
	const TScores stood =
		runDefault(lost, {"motion_prior.max_decel_mps2=0", "pose_estimation.unconstrained_axis_after_gap=false"});
	print("long corridor, readings lost 10 s, default", kept);
	print("long corridor, readings lost 10 s, neither remedy", stood);
	EXPECT_GT(stood.ate_m, 0.9 * stood.odometry_ate_m);  // measured 3.80 m against 3.82: this test can fail
	EXPECT_LT(kept.ate_m, 0.25 * stood.ate_m);  // measured 0.168 m (0.31 with the velocity held alone)
}

TEST(FrontEndScenarios, ReadingsLostDownACorridorAtAScanPerSecondLeaveTheAxisToThePrior)
{
	// The same loss with a scan per second (csail's spacing): 1 m/s is shed
	// in 0.5 s at max_decel_mps2, so the loss is not one "at speed" and the
	// velocity is re-measured from the estimates. Down the bare corridor the
	// matches held the robot on the last keyframe and that velocity fell to
	// zero: the estimate stood through the fault. Now the axis the scan
	// leaves loose is left to the constant-velocity prior after lost
	// readings too.
	hslam::testing::CTempDir dir;
	const auto [kept, stood] = faultAtOneHertz("long-corridor", "drop", "pose_estimation.unconstrained_axis_after_gap=false", dir);
	EXPECT_GT(stood.ate_m, 0.9 * stood.odometry_ate_m);  // measured 3.87 m against 3.77: this test can fail
	EXPECT_LT(kept.ate_m, 0.05 * stood.ate_m);  // measured 0.100 m
}

TEST(FrontEndScenarios, ReadingsFrozenAtSpeedDownACorridorKeepTheVelocity)
{
	// The same fault with the readings frozen (exact zeros) instead of lost:
	// a freeze is only declared at the third zero, and the estimates of the
	// first two followed the zeros. The velocity re-measured from those
	// estimates decayed (0.8 -> 0.5 m/s within a second: ATE 1.63 m). Now
	// the velocity from before the zeros is held through the fault, the first
	// two zeros are unknown motion rather than a stop, and the corridor's
	// axis is left to the prior after them; the counterfactual switches off
	// all three.
	hslam::testing::CTempDir dir;
	const auto frozen = simulated("long-corridor", dir, fault10sAt30("freeze"));
	const TScores held = runDefault(frozen);
	const TScores off = runDefault(frozen, {"motion_prior.max_decel_mps2=0", "motion_prior.zeros_after_motion_unknown=false",
											"pose_estimation.unconstrained_axis_after_freeze=false"});
	print("long corridor, readings frozen 10 s, default", held);
	print("long corridor, readings frozen 10 s, no remedy", off);
	EXPECT_LT(held.ate_m, 0.6);  // measured 0.160 m (0.378 with the velocity held alone)
	EXPECT_LT(held.ate_m, 0.2 * off.ate_m);  // measured 4.04 m (odometry 3.76)
}

TEST(FrontEndScenarios, ReadingsFrozenAtAScanPerSecondAreUnknownMotionUntilDeclared)
{
	// Readings frozen for 10 s at 0.8 m/s with a scan per second: a stop
	// within one interval is possible at max_decel_mps2, so the zeros were
	// followed as a stop for the two scans before they count as frozen; the
	// velocity re-measured from those estimates was zero, and the estimate
	// stood through the fault (as odometry). Now zeros after motion are
	// unknown motion from the first: the scans decide between moving on and
	// a stop.
	hslam::testing::CTempDir dir;
	const auto [moved, stood] = faultAtOneHertz("corridor", "freeze", "motion_prior.zeros_after_motion_unknown=false", dir);
	EXPECT_GT(stood.ate_m, 0.8 * stood.odometry_ate_m);  // measured 2.53 m against 2.63: this test can fail
	EXPECT_LT(moved.ate_m, 0.1 * stood.ate_m);  // measured 0.094 m
}

TEST(FrontEndScenarios, CreepingReadingsAtAScanPerSecondCountOnlyTheRefusedTracksOwnSeed)
{
	// The floor at 1 Hz with readings at 1 % of the motion (the stress
	// matrix's slowscan+creep): ICP runs from the standstill and straight
	// seeds too. The result counted as the refused track was the one at the
	// index where the refused seed would have been, also when there was none
	// (the standstill seed's result): a wrong refusal, a velocity measured from
	// a stop, and the estimate stood (10.6 m against odometry's 23.7).
	hslam::testing::CTempDir dir;
	const auto folder =
		simulated("floor", dir, "--set odometry.fault=freeze --set odometry.fault_motion_scale=0.01 --set laser.rate_hz=1");
	const TScores s = runDefault(folder);
	print("floor at 1 Hz, readings creeping", s);
	EXPECT_GT(s.odometry_ate_m, 15.0);  // the class: odometry is useless (23.7 m)
	EXPECT_LT(s.ate_m, 3.0);  // measured 1.37 m (10.6 m with the wrong index)
}

TEST(FrontEndScenarios, ReadingsFrozenDownALongCorridorAtAScanPerSecondLeaveTheAxisToThePrior)
{
	// As with lost readings at 1 Hz: the scans of the bare corridor hold
	// next to nothing along its axis, ICP measured the standstill there, and
	// the velocity re-measured from those estimates fell to zero, so the
	// estimate stood through the 10 s freeze (as odometry). After readings
	// that froze after motion the axis is left to the prior too.
	hslam::testing::CTempDir dir;
	const auto [kept, stood] =
		faultAtOneHertz("long-corridor", "freeze", "pose_estimation.unconstrained_axis_after_freeze=false", dir);
	EXPECT_GT(stood.ate_m, 0.9 * stood.odometry_ate_m);  // measured 3.70 m against 3.77: this test can fail
	EXPECT_LT(kept.ate_m, 0.05 * stood.ate_m);  // measured 0.112 m
}

namespace
{
/** The scan a laser mounted upside down takes of the same world: its own
 * beams sweep the other way (the beam at scan angle a looks along -a on the
 * robot), and its sensor pose says so with a roll of 180 deg, as
 * rawlog-grabber's pose_roll = 180 records it. */
void turnLaserUpsideDown(io::TRawlogEntry& e)
{
	auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(e.observation.get());
	if (!scan) return;
	const size_t n = scan->getScanSize();
	std::vector<float> ranges(n);
	std::vector<char> valid(n);
	for (size_t i = 0; i < n; ++i) ranges[i] = scan->getScanRange(n - 1 - i), valid[i] = scan->getScanRangeValidity(n - 1 - i);
	for (size_t i = 0; i < n; ++i) scan->setScanRange(i, ranges[i]), scan->setScanRangeValidity(i, valid[i] != 0);
	const auto& p = scan->sensorPose;
	scan->sensorPose = mrpt::poses::CPose3D(p.x(), p.y(), p.z(), p.yaw(), 0, M_PI);
}
}  // namespace

TEST(FrontEndScenarios, LaserMountedUpsideDownIsReadThroughItsSensorPose)
{
	// The lab sample's laser is at yaw 0, symmetric: mounted upside down it
	// measures the same ranges in reverse order. Read with the 2D part of
	// its sensor pose only, every scan was the world mirrored.
	const TScores level = runDefault(shipped("lab"));
	const TScores upsideDown = runDefault(shipped("lab"), {}, 0, turnLaserUpsideDown);
	print("lab", level);
	print("lab, laser upside down", upsideDown);
	EXPECT_NEAR(upsideDown.ate_m, level.ate_m, 0.2 * level.ate_m + 0.002);
}

namespace
{
/** Where the mast's returns lie on the robot (laser 21 mm ahead, beams at
 * -+80 deg, 0.15 m). */
constexpr double kMastX_m = 0.021 + 0.15 * 0.17365, kMastY_m = 0.15 * 0.98481;

/** A mast beside the laser: three beams each side see it 0.15 m away. */
void addMast(io::TRawlogEntry& e)
{
	auto* scan = dynamic_cast<mrpt::obs::CObservation2DRangeScan*>(e.observation.get());
	if (!scan) return;
	const size_t n = scan->getScanSize();  // 181 beams over 180 deg: beam 10 is at -80 deg
	for (size_t i : {size_t(9), size_t(10), size_t(11), n - 12, n - 11, n - 10})
		scan->setScanRange(i, 0.15f), scan->setScanRangeValidity(i, true);
}

struct TPathCells
{
	size_t occupied = 0, visited = 0;  //!< grid cells where the mast was along the path (occupied ones)
	size_t dropped = 0;  //!< returns the pipeline dropped inside the robot
	double ate_m = 0;
};

/** Runs the default pipeline on `folder` with `edit` and counts the grid
 * cells where the mast stood, at each estimated pose, that ended occupied:
 * the robot's own returns, mapped along where it went. */
TPathCells pathCells(const std::string& folder, const std::vector<std::string>& overrides, const TEntryEdit& edit)
{
	std::vector<std::string> o{"process.laser_label=LASER"};
	o.insert(o.end(), overrides.begin(), overrides.end());
	slam::CMappingPipeline pipeline(
		common::loadConfigWithOverrides(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini", o));
	io::CRawlogReader reader(folder + "/sim.rawlog");
	for (io::TRawlogEntry e; reader.next(e);) edit(e), pipeline.processEntry(e);
	TPathCells out;
	std::set<std::pair<int, int>> seen;
	const auto& grid = pipeline.grid();
	for (const auto& p : pipeline.trajectory())
		for (const double side : {-1.0, 1.0})
		{
			double x = 0, y = 0;
			mrpt::poses::CPose2D(p.pose).composePoint(kMastX_m, side * kMastY_m, x, y);
			const auto cell = grid.geometry().cellOf(x, y);
			if (!seen.insert({cell.gx, cell.gy}).second) continue;
			++out.visited;
			if (grid.occupancyProbability(cell) > 0.5) ++out.occupied;
		}
	out.dropped = pipeline.counters().laser_returns_inside_robot;
	out.ate_m = eval::evaluateTrajectory(common::readTumFile(folder + "/ground_truth.tum"), pipeline.trajectory())
					.ate.position_m.rmse;
	return out;
}
}  // namespace

TEST(FrontEndScenarios, ReturnsInsideTheRobotAreNotMapped)
{
	// A return inside the robot's outline ([process] footprint_*, a Pioneer
	// 3-DX by default) is the robot: here a mast beside the laser, 0.15 m
	// off, seen by six beams of every scan of the lab sample.
	const TPathCells dropped = pathCells(shipped("lab"), {}, addMast);
	const TPathCells mapped = pathCells(
		shipped("lab"), {"process.footprint_front_m=0", "process.footprint_rear_m=0", "process.footprint_half_width_m=0"},
		addMast);
	std::cout << "lab with a mast: cells along the path where the mast was, occupied " << dropped.occupied << " of " << dropped.visited
			  << " (returns dropped " << dropped.dropped << ", ATE " << dropped.ate_m << " m); kept: " << mapped.occupied
			  << " of " << mapped.visited << " (ATE " << mapped.ate_m << " m)\n";
	EXPECT_GT(dropped.dropped, 1000u);
	EXPECT_EQ(dropped.occupied, 0u);
	EXPECT_GT(mapped.occupied, 10u);  // this test can fail
	EXPECT_LT(dropped.ate_m, 0.03);
}

TEST(FrontEndScenarios, LongCorridorLeavesTheAxisToOdometry)
{
	hslam::testing::CTempDir dir;
	const TScores s = runDefault(simulated("long-corridor", dir));
	print("long corridor", s);
	// measured ATE 0.209 m (odometry 0.683; before: 4.2 m), RPE 5 m 0.019 m
	// (odometry 0.046; before: 0.43 m, the matcher added error along the axis)
	EXPECT_LT(s.ate_m, 0.5 * s.odometry_ate_m);
	EXPECT_LT(s.rpe5_m, 0.75 * s.odometry_rpe5_m);
}

TEST(FrontEndScenarios, FastDriveWithNoisyOdometryKeepsTheMapsHeading)
{
	// The 200 m corridor at 1.2 m/s with ten times the sample's odometry
	// noise (stress matrix variant fast+noisy): ICP ran every 0.5 m of
	// odometry travel, the line matcher in between (frame to frame). A
	// keyframe added at a line step's pose carried odometry's heading error
	// into the ICP reference, and the next ICP matches agreed with that
	// map: the estimate's heading followed odometry's by 10 deg. Keyframes
	// now come only where ICP placed the scan, and a keyframe due runs ICP
	// ([pose_estimation] keyframes_after_icp_only).
	hslam::testing::CTempDir dir;
	const auto folder = simulated("long-corridor", dir,
								  "--set path.cruise_speed_mps=1.2 --set path.turn_rate_deg_s=100 "
								  "--set robot.wheel_noise_m_per_sqrt_m=0.01 --set robot.rotation_noise_rad_per_sqrt_rad=0.03");
	const TRemedy r = withAndWithout(folder, "pose_estimation.keyframes_after_icp_only=false", "fast, noisy corridor");
	EXPECT_LT(r.on.ate_m, 0.2 * r.on.odometry_ate_m);  // measured 0.371 m (odometry 2.80 m)
	EXPECT_LT(r.on.rpe5_m, 0.5 * r.on.odometry_rpe5_m);  // measured 0.056 m (odometry 0.264 m)
	// measured 1.08 m (before [odometry_timing] max_cost_ratio = 0.5,
	// hslam-process also fitted a 0.15 s lead to the slip and ran a second
	// pass with it: 2.71 m): this test can fail
	EXPECT_LT(r.on.ate_m, 0.5 * r.off.ate_m);
}

TEST(FrontEndScenarios, LongRangeLaserDownACorridorIsNotPinnedByGrazingPoints)
{
	// The corridor sample seen by a 180 deg, 0.5 deg, 20 m scanner (an LMS
	// 291-like one instead of the LMS200's 1 deg and 8 m): far down the
	// corridor its side walls are sampled every 1-2 m, and at the coarse
	// pairing stages (0.5 m + 5 deg x range) point matching pairs those
	// samples with the wrong places along the axis. Iterating each such
	// stage to a 1e-6 step (MRPT's rule) lets the pose creep along the axis
	// pair flip by pair flip; ending the coarse stages at 1 % of their
	// pairing distance (the default) stops the creep, as does not aligning
	// the grazing points (max_incidence_deg).
	hslam::testing::CTempDir dir;
	const auto folder = simulated("corridor", dir, customLaser(180, 0.5, 20));
	const TScores byDefault = runDefault(folder);
	// (the covariance counting information per length of wall, [icp]
	// covariance_full_weight_spacing_m, also keeps the creep out: 0.215 m;
	// the counterfactuals count every beam)
	// (refusing matches that fit worse than the prediction, [pose_estimation]
	// max_fit_loss_vs_prediction, stops the creep as well: 0.036 m; the
	// counterfactuals go without it)
	// (and only ICP placing keyframes contains it too: 0.310 m; the
	// counterfactuals pin the old keyframe policy)
	// (a stall declared only for readings that creep, [motion_prior]
	// stall_needs_creeping, partly: 0.339 m; the counterfactuals go without it
	// and without the wide search after a poor match that came with it)
	const TScores mrptRule =
		runDefault(folder, {"icp.stage_step_fraction=0", "icp.covariance_full_weight_spacing_m=0",
							"pose_estimation.max_fit_loss_vs_prediction=-1", kAnyKeyframes, kNoSlipSearch, kStallOnAnyRefusal});
	const TScores grazingOut =
		runDefault(folder, {"icp.stage_step_fraction=0", "icp.max_incidence_deg=85", "icp.covariance_full_weight_spacing_m=0",
							"pose_estimation.max_fit_loss_vs_prediction=-1", kAnyKeyframes, kNoSlipSearch, kStallOnAnyRefusal});
	print("corridor at 20 m, default", byDefault);
	print("corridor at 20 m, every stage to 1e-6", mrptRule);
	print("corridor at 20 m, every stage to 1e-6, grazing points not aligned", grazingOut);
	EXPECT_LT(byDefault.ate_m, 0.1);  // measured 0.020 m (odometry 0.83 m)
	EXPECT_GT(mrptRule.ate_m, 0.4);  // measured 0.538 m: this test can fail
	EXPECT_LT(grazingOut.ate_m, 0.15);  // measured 0.043 m
	EXPECT_LT(byDefault.ate_m, 0.25 * byDefault.odometry_ate_m);
}

TEST(FrontEndScenarios, LongRangeLaserAroundAFloorLeavesTheAxisToOdometry)
{
	// The floor sample's LMS200 reading out to 30 m instead of 8 m (stress
	// matrix "far"): down the ring corridor the only line across the axis is
	// a far, sparsely sampled one, and a direction that one line alone
	// constrains leaves no residual. The line matcher claimed its floor of
	// 0.01 m there while its matches were 1-11 cm off; the filter believed
	// them over odometry and the path came out 0.7 % short. With the lines'
	// own rho variances carried into the covariance (the default) the axis is
	// left to odometry where that line is poor.
	hslam::testing::CTempDir dir;
	const auto folder = simulated("floor", dir, "--set laser.max_range_m=30");
	const TRemedy r = withAndWithout(folder, "line_matching.rho_variance_covariance=false", "floor at 30 m");
	// measured 0.048 m, 5 m error 0.021 m (0.115 and 0.030 before matches
	// fitting worse than the prediction were refused; odometry 0.641, 0.030)
	EXPECT_LT(r.on.ate_m, 0.15);
	EXPECT_GT(r.off.ate_m, 0.18);  // measured 0.207 m: this test can fail
	EXPECT_LT(r.on.rpe5_m, 1.1 * r.on.odometry_rpe5_m);
	EXPECT_GT(r.off.rpe5_m, 1.5 * r.off.odometry_rpe5_m);  // measured 0.052 m: worse than odometry
}

TEST(FrontEndScenarios, LaserOnlyWithAnEightMetreScannerIsNotPinnedToTheLastKeyframe)
{
	// The laser-only sample's building (readings creeping at 1 %) seen by an
	// 8 m scanner instead of 30 m: down the ring corridor point ICP held the
	// estimate where the scan's wall samples fell on the last keyframe's,
	// claiming a few centimetres along the axis, while the robot drove 6 m
	// on. While odometry is stalled, ICP is refined point-to-line and judged
	// by the point-to-segment fit as a standstill claim is ([pose_estimation]
	// stalled_point_to_line), and a direction the scan's own surfaces leave
	// unconstrained (a bare corridor's axis out of the scanner's reach) is
	// left to the constant-velocity prior (stalled_unconstrained_max_fraction;
	// only scan points the keyframes hold count).
	hslam::testing::CTempDir dir;
	const auto folder = simulated("laser-only", dir, "--set laser.max_range_m=8");
	const TScores both = runDefault(folder);
	const TScores pinnedAxis = runDefault(folder, {"pose_estimation.stalled_unconstrained_max_fraction=0"});
	const TScores neither = runDefault(folder, {"pose_estimation.stalled_unconstrained_max_fraction=0",
												"pose_estimation.stalled_point_to_line=false"});
	print("laser only at 8 m, default", both);
	print("laser only at 8 m, the axis measured by ICP's covariance", pinnedAxis);
	print("laser only at 8 m, neither", neither);
	// online estimates: measured 0.071, 2.49 and 3.54 m (odometry 9.22 m;
	// 2.53, 2.16 and 5.42 m before the twentieth round)
	EXPECT_LT(both.ate_m, 0.02 * both.odometry_ate_m);
	EXPECT_GT(pinnedAxis.ate_m, 10.0 * both.ate_m);
	EXPECT_GT(neither.ate_m, 1.3 * pinnedAxis.ate_m);
}

TEST(FrontEndScenarios, AnIcpMatchFittingWorseThanThePredictionIsNotUsed)
{
	// The corridor sample's LMS200 reading out to 30 m (stress matrix "far"):
	// driving back past a door recess, ICP from a seed 2.5 cm off ends 0.58 m
	// along the axis, where six far points fall next to reference samples one
	// beam spacing on and pair. It pairs more points there but fits worse
	// than the prediction; its NIS (49.9) passes the gate. Not used by
	// default ([pose_estimation] max_fit_loss_vs_prediction).
	hslam::testing::CTempDir dir;
	const auto folder = simulated("corridor", dir, "--set laser.max_range_m=30");
	const TRemedy r = withAndWithout(folder, "pose_estimation.max_fit_loss_vs_prediction=-1", "corridor at 30 m");
	EXPECT_LT(r.on.ate_m, 0.12);  // measured 0.043 m (odometry 0.826 m)
	EXPECT_LT(r.on.rpe5_m, 0.5 * r.on.odometry_rpe5_m);  // measured 0.014 m (odometry 0.039 m)
	// Only ICP placing keyframes avoids this slip as well (without the rule:
	// 0.016 m); under the old keyframe policy the rule still decides.
	const TScores off = runDefault(folder, {"pose_estimation.max_fit_loss_vs_prediction=-1", kAnyKeyframes});
	const TScores oldOn = runDefault(folder, {kAnyKeyframes});
	print("corridor at 30 m, any keyframes, the rule off", off);
	print("corridor at 30 m, any keyframes", oldOn);
	EXPECT_GT(off.rpe5_m, off.odometry_rpe5_m);  // measured 0.158 m: the slip, worse than odometry
	EXPECT_LT(oldOn.rpe5_m, 0.5 * oldOn.odometry_rpe5_m);
}

TEST(FrontEndScenarios, WornTyresAreCalibratedOutByMatching)
{
	// The floor sample with wheels 5 % smaller than nominal (Borenstein's
	// Es = 0.95): odometry overstates every distance by 5 %, and where the
	// corridors leave the axis to odometry the fused estimate inherits it.
	// [odometry_self_calibration] fits the scale from the accepted matches
	// and applies it; with exact odometry it stays within the front-end's
	// own bias and is not applied.
	hslam::testing::CTempDir dir;
	const auto worn = simulated("floor", dir, "--set robot.es_wheel_scale_ratio=0.95");
	const auto [calibrated, uncalibrated] =
		withAndWithout(worn, "odometry_self_calibration.enabled=false", "floor, worn tyres");
	std::cout << "fitted distance scale " << calibrated.odometry_scale << " (truth 0.95)\n";
	EXPECT_TRUE(calibrated.odometry_scale_applied);
	EXPECT_LT(calibrated.odometry_scale, 0.985);  // measured 0.97x: the match leaves part to odometry
	EXPECT_GT(uncalibrated.ate_m, 0.8);  // measured 1.02 m: this test can fail
	EXPECT_LT(calibrated.ate_m, 0.7 * uncalibrated.ate_m);  // measured 0.43 m (0.55 m without the heading terms)
	hslam::testing::CTempDir exactDir;
	const TScores exact = runDefault(simulated("floor", exactDir));
	EXPECT_FALSE(exact.odometry_scale_applied) << "fitted " << exact.odometry_scale;
	EXPECT_NEAR(exact.odometry_scale, 1.0, 0.006);  // measured 0.998
}

TEST(FrontEndScenarios, UnequalWheelsAreCalibratedOutOfTheHeading)
{
	// The floor sample with one wheel 2 % larger (UMBmark's Ed = 1.02): the
	// odometry gains 3.4 deg per metre it does not turn. Each match fixes
	// most of a step's heading, but the fused estimate keeps part of it and
	// the keyframes it inserts carry that on: the map bends round.
	// [odometry_self_calibration] estimate_heading fits the curvature from
	// the accepted matches and corrects the odometry.
	hslam::testing::CTempDir dir;
	const auto bent = simulated("floor", dir, "--set robot.ed_wheel_diameter_ratio=1.02");
	const auto [calibrated, uncalibrated] =
		withAndWithout(bent, "odometry_self_calibration.estimate_heading=false", "floor, unequal wheels");
	std::cout << "fitted curvature " << calibrated.odometry_curvature_rad_per_m * 180 / M_PI << " deg/m\n";
	EXPECT_GT(uncalibrated.ate_m, 3.0);  // measured 5.8 m (odometry 36.6 m): this test can fail
	EXPECT_TRUE(calibrated.odometry_heading_applied);
	EXPECT_NEAR(std::abs(calibrated.odometry_curvature_rad_per_m) * 180 / M_PI, 3.4, 0.6);  // measured 3.1
	EXPECT_LT(calibrated.ate_m, 0.3 * uncalibrated.ate_m);  // measured 0.95 m
}

TEST(FrontEndScenarios, ShortRangeScannerInAnOpenHallIsNoWorseThanOdometry)
{
	// The open hall seen by a 5.6 m Hokuyo URG-04LX: most scans hold a pillar
	// or two and a crate corner, 10-20 points that pair perfectly in many
	// places. Such matches were taken as good, and as proof that the
	// prediction was wrong: the estimate jumped 10 m and 120 deg (ATE 9.9 m).
	// Now a match pairing fewer than [icp] min_good_points is weak, a weak
	// ICP match meets the textbook gate ([ukf] weak_gate_nis) and only a
	// match that pins the translation down refutes the prediction. Such a
	// match is also restarted from rotated seeds ([icp]
	// restart_below_good_points): at t = 34.6 s the first result, 13 points
	// paired at fit 0.71, lay 2 m and 21 deg from the prediction and moved
	// the estimate 0.31 m and 3.4 deg off the truth.
	hslam::testing::CTempDir dir;
	const auto hall = simulated("open-hall", dir, customLaser(240, 0.36, 5.6, 10));
	// Since the twenty-third round only ICP places keyframes, and a scan of
	// fewer than min_good_points is not made one without it: here no ICP
	// match is fused after the first keyframe, and the estimate is the line
	// matcher's and odometry's (four other seeds: RPE 5 m 0.074 m against
	// odometry's 0.078, 0.19-0.23 m when such scans were made keyframes).
	const TScores s = runDefault(hall);
	print("open hall, 5.6 m scanner", s);
	EXPECT_LT(s.ate_m, 0.95 * s.odometry_ate_m);  // measured 0.725 m against 0.780 m
	EXPECT_LT(s.rpe5_m, 1.05 * s.odometry_rpe5_m);  // measured 0.0794 against 0.0785 m
	// The remedies for few-point matches, measured under the old keyframe
	// policy, where ICP matched such scans, and without the wide search
	// after a poor match, which came later (with it the old policy's run is
	// 0.655 m: pillars alike give the search more than one place).
	const TScores old = runDefault(hall, {kAnyKeyframes, kNoSlipSearch});
	const TScores byGoodness = runDefault(hall, {"icp.min_good_points=0", kAnyKeyframes, kNoSlipSearch});
	const TScores notRestarted = runDefault(hall, {"icp.restart_below_good_points=false", kAnyKeyframes, kNoSlipSearch});
	print("open hall, 5.6 m scanner, any keyframes", old);
	print("open hall, 5.6 m scanner, any keyframes, few-point matches good", byGoodness);
	print("open hall, 5.6 m scanner, any keyframes, few-point matches not restarted", notRestarted);
	EXPECT_LT(old.ate_m, 0.8 * old.odometry_ate_m);  // measured 0.58 m against 0.78 m
	EXPECT_LT(old.ate_m, 0.85 * notRestarted.ate_m);  // measured 0.73 m: this test can fail
	EXPECT_LT(old.rpe5_m, 0.85 * notRestarted.rpe5_m);  // measured 0.102 against 0.130 m (odometry 0.078)
	EXPECT_LT(notRestarted.ate_m, 0.9 * byGoodness.ate_m);  // measured 0.84 m: this test can fail
}

TEST(FrontEndScenarios, MatchesTheScanProvesRightAreTakenBeyondTheGate)
{
	// The floor sample with every odometry reading 0.3 s old ([odometry]
	// fault = lag): at each corner the steps between scans miss up to 8 deg
	// of the turn and the next ones have it, heavy-tailed heading errors like
	// csail's fast turns. Matches that fit the keyframes well where the scan
	// at the predicted pose does not are taken beyond the NIS gate ([ukf]
	// refuted_prediction_min_fit); the gate alone refused them and the
	// heading slipped 15 deg at the third corner.
	hslam::testing::CTempDir dir;
	const auto lagged = simulated("floor", dir, "--set odometry.fault=lag --set odometry.fault_lag_s=0.3");
	// Measured under the old keyframe policy (kAnyKeyframes). Where only
	// ICP places keyframes the gate alone no longer slips here: 0.092 m,
	// and 0.203 m with the rule (docs/pose-estimation.md, twenty-third round).
	const TScores taken = runDefault(lagged, {"odometry_timing.estimate_offset=false", kAnyKeyframes});
	const TScores gated =
		runDefault(lagged, {"odometry_timing.estimate_offset=false", "ukf.refuted_prediction_min_fit=0", kAnyKeyframes});
	print("floor, odometry 0.3 s late, refuted predictions widened", taken);
	print("floor, odometry 0.3 s late, the gate alone", gated);
	EXPECT_GT(gated.ate_m, 1.2);  // measured 1.47 m: this test can fail
	EXPECT_LT(taken.ate_m, 0.75 * gated.ate_m);  // measured 0.86 m
	// Still worse than the late odometry itself (0.64 m) without the
	// offset's own fit: the next test.
}

TEST(FrontEndScenarios, LateOdometryIsReadAtTheScansTime)
{
	// The same lagged floor: [odometry_timing] fits the offset from the
	// matched heading changes at the first corner and from then on reads the
	// odometry at each scan's time (the scan waits for the reading after it).
	hslam::testing::CTempDir dir;
	const auto lagged = simulated("floor", dir, "--set odometry.fault=lag --set odometry.fault_lag_s=0.3");
	std::vector<std::string> o{"process.laser_label=LASER"};
	const auto cfg = common::loadConfigWithOverrides(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini", o);
	slam::CMappingPipeline pipeline(cfg);
	io::CRawlogReader reader(lagged + "/sim.rawlog");
	for (io::TRawlogEntry e; reader.next(e);) pipeline.processEntry(e);
	pipeline.finish();
	EXPECT_NEAR(pipeline.odometryOffsetInUse_s(), 0.3, 0.05);  // measured 0.27 (fused headings lean to odometry)
	EXPECT_GE(pipeline.counters().odometry_offset_changes, 1u);
	const TScores fitted = runDefault(lagged);
	const TScores given = runDefault(lagged, {"odometry_timing.offset_s=0.3", "odometry_timing.estimate_offset=false"});
	const TScores none = runDefault(lagged, {"odometry_timing.estimate_offset=false"});
	print("floor, odometry 0.3 s late, offset fitted", fitted);
	print("floor, odometry 0.3 s late, offset given", given);
	print("floor, odometry 0.3 s late, no offset", none);
	// In one pass the offset is applied only once its fit is clear ([odometry_timing]
	// max_cost_ratio), late in the run: measured 0.195 m against 0.60 m.
	EXPECT_LT(fitted.ate_m, fitted.odometry_ate_m);
	EXPECT_LT(given.ate_m, 0.15);  // measured 0.055 m (0.070 m on time)
	// hslam-process runs the rawlog again with the fitted offset from the
	// start ([odometry_timing] second_pass): the first corner is read right too.
	batch::TBatchRequest request;
	request.config_file = std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini";
	request.overrides = {"process.laser_label=LASER", "output.write_tiles=false"};
	request.input_rawlog = lagged + "/sim.rawlog";
	request.ground_truth_tum = lagged + "/ground_truth.tum";
	request.output_dir = dir.file("batch");
	request.show_progress = false;
	std::ostringstream out, err;
	const auto twice = batch::CBatchProcessor(request, out, err).run();
	ASSERT_TRUE(twice.evaluation.has_value());
	std::cout << "floor, odometry 0.3 s late, hslam-process (second pass): ATE "
			  << twice.evaluation->ate.position_m.rmse << " m\n";
	EXPECT_NE(out.str().find("second pass"), std::string::npos);
	EXPECT_LT(twice.evaluation->ate.position_m.rmse, 0.15);  // measured 0.060 m
	EXPECT_LT(twice.evaluation->ate.position_m.rmse, 0.6 * none.ate_m);  // 0.159 m without the offset
	// with a reference, evaluation.json also says how well each trajectory
	// explains the scans (eval/scan_consistency.h)
	const std::string json = hslam::testing::readTextFile(dir.file("batch") + "/evaluation.json");
	EXPECT_NE(json.find("\"scan_misfit_reference_mean_m\": "), std::string::npos) << json;
	EXPECT_NE(json.find("\"scan_pairs_estimate_clearly_worse\": "), std::string::npos) << json;
	EXPECT_NE(out.str().find("Scan consistency"), std::string::npos);
}

TEST(FrontEndScenarios, DenseScannerMatchedWithEveryKthPointStaysOnTrack)
{
	// [pose_estimation] max_match_points: the lab driven with a 541-beam
	// LMS100 (270 deg, 0.5 deg), matched with every point and with every 3rd
	// (limit 200). Measured (front-end alone): 0.0041 m and 0.0082 m: fewer
	// points cost accuracy (off by default), but the robot stays tracked.
	hslam::testing::CTempDir dir;
	const std::string lab = simulated("lab", dir, "--set laser.preset=lms100");
	const auto every = runDefault(lab, {"loop_closure.enabled=false"});
	const auto thinned = runDefault(lab, {"loop_closure.enabled=false", "pose_estimation.max_match_points=200"});
	print("lab, LMS100, every point", every);
	print("lab, LMS100, every 3rd point", thinned);
	EXPECT_LT(every.ate_m, 0.01);
	EXPECT_LT(thinned.ate_m, 0.02);
	EXPECT_NE(every.ate_m, thinned.ate_m);  // the limit reaches the matchers
	EXPECT_LT(thinned.ate_m, 0.5 * thinned.odometry_ate_m);  // odometry 0.030 m
}

TEST(FrontEndScenarios, OpenHallIsBetterThanOdometry)
{
	hslam::testing::CTempDir dir;
	const TScores s = runDefault(simulated("open-hall", dir));
	print("open hall", s);
	EXPECT_LT(s.ate_m, 0.2);  // measured 0.087 m (odometry 0.78 m)
}

TEST(FrontEndScenarios, PeopleCrossingCloseAreLeftOutOfMatching)
{
	const TScores with = runDefault(shipped("people-crossing"));
	const TScores without = runDefault(shipped("people-crossing"), {"dynamic_objects.exclude_from_matching=false"});
	print("people crossing, excluded from matching", with);
	print("people crossing, matched", without);
	// Six people crossing close disturb neither: measured 0.031 m with the
	// people's beams left out, 0.025 m with them matched (odometry 0.74 m).
	// Leaving them out is not better on this sample: over five start offsets
	// (scripts/offset-ensemble.sh) the medians are 0.033 against 0.023 m, the
	// previous seed rule gave 0.031 / 0.038 m at this start but the same
	// medians (docs/pose-estimation.md, "People out of matching, measured").
	EXPECT_LT(with.ate_m, 0.05);
	EXPECT_LT(without.ate_m, 0.05);
	EXPECT_LT(with.ate_m, 0.1 * with.odometry_ate_m);
}
