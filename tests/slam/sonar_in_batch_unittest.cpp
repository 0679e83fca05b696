/* The sonar stage of the batch job (CMappingPipeline + CSonarMappingStage):
 * grid updates from CObservationRange, TBF corners against the ground truth
 * of the simulated lab sample, the pose the readings are inserted at, and
 * that `[sonar_model] enabled = false` leaves the laser map untouched. */
#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/point_landmark_score.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/sim/scene.h>
#include <hslam/batch/CBatchProcessor.h>
#include <hslam/slam/CSonarMappingStage.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hslam;

namespace
{
const std::string kLab = std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/lab";
using hslam::slam::testing::kDefaultIni;

using hslam::slam::testing::runBatch;

mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path)
{
	mrpt::maps::COccupancyGridMap2D grid;
	mrpt::io::CFileGZInputStream in(path);
	mrpt::serialization::archiveFrom(in) >> grid;
	return grid;
}

std::string readText(const std::string& path)
{
	std::ifstream f(path);
	std::stringstream s;
	s << f.rdbuf();
	return s.str();
}

/** Number of cells whose stored value differs (the grids must have the same extent). */
size_t differingCells(const mrpt::maps::COccupancyGridMap2D& a, const mrpt::maps::COccupancyGridMap2D& b)
{
	EXPECT_EQ(a.getSizeX(), b.getSizeX());
	EXPECT_EQ(a.getSizeY(), b.getSizeY());
	EXPECT_NEAR(a.getXMin(), b.getXMin(), 1e-9);
	EXPECT_NEAR(a.getYMin(), b.getYMin(), 1e-9);
	if (a.getSizeX() != b.getSizeX() || a.getSizeY() != b.getSizeY()) return a.getSizeX() * a.getSizeY();
	size_t n = 0;
	for (unsigned y = 0; y < a.getSizeY(); ++y)
		for (unsigned x = 0; x < a.getSizeX(); ++x) n += a.getCell(x, y) != b.getCell(x, y);
	return n;
}

/** The lab sample's rawlog without its sonar observations. */
void writeWithoutSonar(const std::string& in, const std::string& out)
{
	mrpt::io::CFileGZOutputStream f(out);
	auto arch = mrpt::serialization::archiveFrom(f);
	io::CRawlogReader reader(in);
	for (io::TRawlogEntry e; reader.next(e);)
	{
		ASSERT_TRUE(e.observation) << "the samples are observations-only rawlogs";
		if (!IS_CLASS(*e.observation, mrpt::obs::CObservationRange)) arch << *e.observation;
	}
}

mrpt::poses::CPose2D firstPose(const common::TTrajectory2D& t)
{
	return {t.front().pose.x, t.front().pose.y, t.front().pose.phi};
}
}  // namespace

TEST(SonarInBatch, LabSampleInsertsSonarAndFindsTrueCorners)
{
	hslam::testing::CTempDir dir;
	const auto result = runBatch(kLab + "/sim.rawlog", dir.path().string(), {"sonar_model.enabled=true"});
	ASSERT_TRUE(result.input_error.empty()) << result.input_error;
	const auto& c = result.counters;
	EXPECT_EQ(c.sonar_observations, 1336u);  // summary.txt: observations_SONAR=1336
	EXPECT_EQ(c.sonar_observations_ignored, 0u);
	// 10688 readings; those with an echo within the 3 m range limit go in.
	EXPECT_GT(c.sonar_readings_inserted, 5000u);
	EXPECT_LT(c.sonar_readings_inserted, 9365u);  // summary.txt: sonar_echoes=9365
	EXPECT_NE(readText(dir.file("timing.csv")).find("sonar_update,1336,"), std::string::npos);
	EXPECT_NE(readText(dir.file("timing.csv")).find("sonar_corners,1336,"), std::string::npos);
	for (const char* f : {"map_sonar_corners.png", "map_laser_only.png", "map_sonar_only.png"})
		EXPECT_TRUE(std::filesystem::exists(dir.path() / f)) << f;

	// TBF corners vs the true point features of the lab: wall corners
	// (corners.csv) and the static circles of the scene (pillar, chair and
	// table legs: thin reflectors that echo like edges, thesis 4.3.2).
	const auto found = eval::readPointsCsv(dir.file("sonar_corners.csv"));
	ASSERT_GE(found.size(), 5u);
	auto truth = eval::readPointsCsv(kLab + "/corners.csv");
	ASSERT_EQ(truth.size(), 16u);
	std::vector<double> radii(truth.size(), 0.0);
	const sim::TScene scene = sim::loadSceneFile(std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-worlds/lab.scene");
	for (const auto& circle : scene.world.circles()) truth.push_back(circle.centre), radii.push_back(circle.radius_m);
	ASSERT_EQ(truth.size(), 16u + 21u);
	const auto mapInWorld = firstPose(common::readTumFile(kLab + "/ground_truth.tum")) +
							(-firstPose(common::readTumFile(dir.file("trajectory.tum"))));
	const auto score = eval::scorePointLandmarks(found, truth, 0.3, mapInWorld, radii);
	EXPECT_GE(score.precision(), 0.7) << score.found_near_truth << " of " << score.found;  // measured: 7 of 7
	// The pillar (6.2, 2.6), r 0.15, passed at 1.1 m twice per loop, is found.
	const auto pillar = eval::scorePointLandmarks(found, {{6.2, 2.6}}, 0.2, mapInWorld, {0.15});
	EXPECT_EQ(pillar.truth_found, 1u);
}

TEST(SonarInBatch, DisabledSonarMappingLeavesTheLaserMapUnchanged)
{
	hslam::testing::CTempDir dir;
	writeWithoutSonar(kLab + "/sim.rawlog", dir.file("no_sonar.rawlog"));
	// Loop closure off: with sonar mapping on the map is not re-rendered from
	// the optimised graph (docs/loop-closure.md), so the three maps compared
	// here are all the online ones.
	const std::string lcOff = "loop_closure.enabled=false";
	const auto noSonar = runBatch(dir.file("no_sonar.rawlog"), dir.file("no_sonar"), {lcOff});
	EXPECT_EQ(noSonar.counters.sonar_observations, 0u);
	const auto off = runBatch(kLab + "/sim.rawlog", dir.file("off"), {"sonar_model.enabled=false", lcOff});
	EXPECT_EQ(off.counters.sonar_observations, 1336u);  // TBF still runs
	EXPECT_EQ(off.counters.sonar_readings_inserted, 0u);
	EXPECT_EQ(readText(dir.file("off/trajectory.tum")), readText(dir.file("no_sonar/trajectory.tum")));
	const auto laserOnly = loadGridmap(dir.file("no_sonar/map.gridmap.gz"));
	EXPECT_EQ(differingCells(loadGridmap(dir.file("off/map.gridmap.gz")), laserOnly), 0u);
	EXPECT_FALSE(std::filesystem::exists(dir.file("off/map_laser_only.png")));  // map.png is laser-only

	// Enabled, the sonars change the map (and only the map: same poses).
	const auto on = runBatch(kLab + "/sim.rawlog", dir.file("on"), {"sonar_model.enabled=true", lcOff});
	EXPECT_EQ(readText(dir.file("on/trajectory.tum")), readText(dir.file("no_sonar/trajectory.tum")));
	const auto fused = loadGridmap(dir.file("on/map.gridmap.gz"));
	size_t knownFused = 0, knownLaser = 0;
	for (const auto* g : {&fused, &laserOnly})
		for (unsigned y = 0; y < g->getSizeY(); ++y)
			for (unsigned x = 0; x < g->getSizeX(); ++x)
				(g == &fused ? knownFused : knownLaser) +=
					benchdata::classifyOccupancy(1.0 - g->getCell(x, y), 0.01) != benchdata::ECellClass::unknown;
	// sonar cones reach cells the 3 m laser did not (measured +495 of 7856,
	// +502 with [icp] engine = mrpt)
	EXPECT_GT(knownFused, knownLaser + 250);
}

TEST(SonarInBatch, SonarLabelSelectsTheObservations)
{
	hslam::testing::CTempDir dir;
	const auto result = runBatch(kLab + "/sim.rawlog", dir.path().string(),
								 {"sonar_model.enabled=true", "process.sonar_label=REAR_SONAR"});
	EXPECT_EQ(result.counters.sonar_observations, 0u);
	EXPECT_EQ(result.counters.sonar_observations_ignored, 1336u);
	EXPECT_EQ(result.counters.sonar_readings_inserted, 0u);
	// no sonar ring used: no sonar outputs (an empty picture, copies of map.png)
	for (const char* f : {"sonar_corners.csv", "map_sonar_corners.png", "map_laser_only.png", "map_sonar_only.png"})
		EXPECT_FALSE(std::filesystem::exists(dir.file(f))) << f;
	EXPECT_TRUE(std::filesystem::exists(dir.file("map.png")));
	const auto labelled = runBatch(kLab + "/sim.rawlog", dir.file("b"), {"process.sonar_label=SONAR"});
	EXPECT_EQ(labelled.counters.sonar_observations, 1336u);
}

TEST(SonarInBatch, ReadingIsInsertedAtTheLatestEstimatePlusPendingOdometry)
{
	// Scan at x = 0, then the robot moves 1 m forward (odometry), then one
	// sonar facing forward reads 1.0 m: the echo is at x = 2 m, not at 1 m
	// (where the pose of the latest scan alone would put it).
	hslam::testing::CTempDir dir;
	{
		mrpt::io::CFileGZOutputStream out(dir.file("s.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(out);
		const auto odometry = [&](double x, double t) {
			mrpt::obs::CObservationOdometry o;
			o.odometry = mrpt::poses::CPose2D(x, 0, 0);
			o.timestamp = mrpt::Clock::fromDouble(t);
			arch << o;
		};
		mrpt::obs::CObservation2DRangeScan scan;  // no valid beam: the laser inserts nothing
		scan.aperture = static_cast<float>(M_PI);
		scan.resizeScan(5);
		for (size_t i = 0; i < 5; ++i) scan.setScanRange(i, 0.0f), scan.setScanRangeValidity(i, false);
		scan.timestamp = mrpt::Clock::fromDouble(1000.0);
		mrpt::obs::CObservationRange sonar;
		sonar.sensorLabel = "SONAR";
		sonar.minSensorDistance = 0.1f;
		sonar.maxSensorDistance = 5.0f;
		sonar.sensorConeApperture = static_cast<float>(30.0 * M_PI / 180.0);
		sonar.sensedData.resize(1);
		sonar.sensedData[0].sensedDistance = 1.0f;
		sonar.sensedData[0].sensorID = 0;
		sonar.timestamp = mrpt::Clock::fromDouble(1001.0);
		odometry(0.0, 1000.0), arch << scan;
		odometry(1.0, 1001.0), arch << sonar;
	}
	const auto result = runBatch(dir.file("s.rawlog"), dir.file("out"),
								 {"pose_estimation.method=odometry", "sonar_model.enabled=true", "sonar_model.weight=1",
								  "dynamic_objects.enabled=false"});
	EXPECT_EQ(result.counters.sonar_readings_inserted, 1u);
	const auto grid = loadGridmap(dir.file("out/map.gridmap.gz"));
	// Highest / lowest occupancy among the cells around x on the beam axis
	// (y = 0 is a cell edge; the fast model updates one row of axis cells).
	const auto occupancyNear = [&](double x, bool highest) {
		double p = highest ? 0.0 : 1.0;
		for (double dx : {-0.1, 0.0, 0.1})
			for (double y : {-0.05, 0.05})
			{
				const double q = 1.0 - grid.getPos(x + dx, y);
				p = highest ? std::max(p, q) : std::min(p, q);
			}
		return p;
	};
	// The arc cell on the axis at ~1.05 m off axis by < 3 deg: s ~ 0.89 ->
	// P = 0.5 + 0.48 s ~ 0.93 (one update; the weight is 1 here).
	EXPECT_GT(occupancyNear(2.0, true), 0.85);
	EXPECT_LE(occupancyNear(1.0, true), 0.5);  // no echo where the latest estimate alone would put it
	EXPECT_LT(occupancyNear(1.5, false), 0.15);  // region 2 on the axis: free, P = 0.5 - 0.48 s
}

TEST(SonarInBatch, DefaultIniDocumentsTheSonarSections)
{
	// [sonar_model] and [tbf] of the default INI state the defaults of the
	// pipeline's option structs (which include the inserter's and detector's).
	mrpt::config::CConfigFile cfg(kDefaultIni);
	slam::TSonarMappingOptions sonarOptions;
	slam::TTbfStageOptions tbfOptions;
	common::loadOptions(sonarOptions, cfg, "sonar_model");  // throws on unknown keys
	common::loadOptions(tbfOptions, cfg, "tbf");
	mrpt::config::CConfigFileMemory a, b;
	common::saveOptions(sonarOptions, a, "s");
	common::saveOptions(tbfOptions, a, "t");
	common::saveOptions(slam::TSonarMappingOptions(), b, "s");
	common::saveOptions(slam::TTbfStageOptions(), b, "t");
	EXPECT_EQ(a.getContent(), b.getContent());
	slam::TProcessOptions process;
	common::loadOptions(process, cfg, "process");
	EXPECT_EQ(process.sonar_label, "");
}
