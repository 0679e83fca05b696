#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CSonarGridInserter.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

using namespace hslam::maps;

namespace
{
double logit(double p) { return std::log(p / (1 - p)); }

// Sensor in the middle of cell (0,0) looking along +x; echo at 1.0 m, so the
// arc's axis cell is (10,0) (centre x = 1.05). Cone 23 deg (+-11.5 deg, the
// thesis' code), R = 5 m, arc +-0.15 m (appendix G.3).
TSonarReading readingAt1m()
{
	TSonarReading r;
	r.sensor = {0.05, 0.05, 0.0};
	r.range_m = 1.0;
	r.cone_aperture_rad = 23.0 * M_PI / 180.0;
	r.sensor_max_range_m = 5.0;
	return r;
}

CSonarGridInserter::TOptions withModel(const std::string& model, double weight = 1.0)
{
	CSonarGridInserter::TOptions o;
	o.model = model;
	o.weight = weight;
	return o;
}

// Expected probability from the header's formula, derived by hand:
// s = ((R - d)/R + (beta - |alpha|)/beta)/2, P = 0.5 +- 0.48 s.
double expectedP(double d, double alphaDeg, bool region1)
{
	const double s = 0.5 * ((5.0 - d) / 5.0 + (11.5 - std::abs(alphaDeg)) / 11.5);
	return region1 ? 0.5 + 0.48 * s : 0.5 - 0.48 * s;
}
}  // namespace

TEST(SonarGridInserter, FastModelUpdatesAxisCellsAndTheArcOnly)
{
	CTiledOccupancyGrid grid;
	CSonarGridInserter fast(withModel("fast"));
	const auto stats = fast.insert(grid, readingAt1m());
	EXPECT_EQ(stats.readings_inserted, 1u);
	// Region 2 along the axis: cells 0..8 (cell 9's centre at 0.95 m is past 1.0 - 0.15).
	EXPECT_NEAR(grid.occupancyProbability({5, 0}), expectedP(0.5, 0, false), 1e-4);  // = 0.044
	EXPECT_NEAR(grid.occupancyProbability({5, 0}), 0.044, 1e-4);
	EXPECT_NEAR(grid.occupancyProbability({8, 0}), expectedP(0.8, 0, false), 1e-4);
	EXPECT_FALSE(grid.isObserved({9, 0}));
	// Off-axis cells inside the cone are NOT updated by the fast model.
	EXPECT_FALSE(grid.isObserved({5, 1}));
	EXPECT_FALSE(grid.isObserved({8, -1}));
	// Region 1: the arc at 1.0 m, axis cell (10,0): d = 1.0, alpha = 0 -> 0.932.
	EXPECT_NEAR(grid.occupancyProbability({10, 0}), 0.932, 1e-4);
	// Arc end at +11.5 deg: (0.05 + cos, 0.05 + sin) = (1.03, 0.249) -> cell (10,2).
	const double d102 = std::hypot(1.0, 0.2), a102 = std::atan2(0.2, 1.0) * 180 / M_PI;
	EXPECT_NEAR(grid.occupancyProbability({10, 2}), expectedP(d102, a102, true), 1e-4);
	EXPECT_FALSE(grid.isObserved({10, 3}));
	EXPECT_FALSE(grid.isObserved({11, 0}));  // the fast arc is one cell thick
	EXPECT_EQ(stats.cells_updated, 9u + 5u);  // 9 axis cells + arc cells (10,-2..2)
}

TEST(SonarGridInserter, StandardModelUpdatesEveryCellOfTheCone)
{
	CTiledOccupancyGrid grid;
	CSonarGridInserter standard(withModel("standard"));
	const auto stats = standard.insert(grid, readingAt1m());
	// Off-axis region-2 cell (5,1): centre (0.55, 0.15), d = 0.5099, alpha = 11.31 deg < 11.5.
	EXPECT_NEAR(grid.occupancyProbability({5, 1}), expectedP(std::hypot(0.5, 0.1), std::atan2(0.1, 0.5) * 180 / M_PI, false),
				1e-4);
	EXPECT_FALSE(grid.isObserved({5, 2}));  // alpha = 21.8 deg: outside the cone
	// Region 1 is the band |d - 1.0| <= 0.15: (9,0) d=0.9, (10,0), (11,0) d=1.1; (12,0) d=1.2 is outside.
	EXPECT_NEAR(grid.occupancyProbability({9, 0}), expectedP(0.9, 0, true), 1e-4);
	EXPECT_NEAR(grid.occupancyProbability({11, 0}), expectedP(1.1, 0, true), 1e-4);
	EXPECT_FALSE(grid.isObserved({12, 0}));
	// Axis cells agree with the fast model.
	EXPECT_NEAR(grid.occupancyProbability({5, 0}), 0.044, 1e-4);
	EXPECT_GE(stats.cells_updated, 25u);  // the fast model updates 14 cells for this reading
}

TEST(SonarGridInserter, RangeLimitAndNoEcho)
{
	TSonarReading far = readingAt1m();
	far.range_m = 4.0;  // beyond the default 3 m limit
	{
		CTiledOccupancyGrid grid;
		const auto stats = CSonarGridInserter().insert(grid, far);
		EXPECT_EQ(stats.readings_skipped, 1u);
		EXPECT_EQ(grid.tileCount(), 0u);
	}
	{
		CSonarGridInserter::TOptions o = withModel("fast");
		o.insert_free_beyond_range = true;
		CTiledOccupancyGrid grid;
		CSonarGridInserter(o).insert(grid, far);
		EXPECT_LT(grid.occupancyProbability({25, 0}), 0.5);  // free up to 3 m
		EXPECT_FALSE(grid.isObserved({40, 0}));  // no arc at 4 m
		EXPECT_FALSE(grid.isObserved({31, 0}));
	}
	TSonarReading none = readingAt1m();
	none.range_m = 0;  // MRPT: 0 = no echo
	CTiledOccupancyGrid grid;
	EXPECT_EQ(CSonarGridInserter().insert(grid, none).readings_skipped, 1u);
	none.range_m = std::nan("");
	EXPECT_EQ(CSonarGridInserter().insert(grid, none).readings_skipped, 1u);
	EXPECT_EQ(grid.tileCount(), 0u);
}

TEST(SonarGridInserter, WeightScalesTheLogOdds)
{
	CTiledOccupancyGrid grid;
	CSonarGridInserter(withModel("fast", 0.25)).insert(grid, readingAt1m());
	EXPECT_NEAR(grid.logOdds({10, 0}), 0.25 * logit(0.932), 2e-3);
	EXPECT_NEAR(grid.logOdds({5, 0}), 0.25 * logit(0.044), 2e-3);
}

TEST(SonarGridInserter, ObservationRangeUsesEachSonarsPose)
{
	mrpt::obs::CObservationRange obs;
	obs.sensorConeApperture = static_cast<float>(23.0 * M_PI / 180.0);
	obs.maxSensorDistance = 5.0f;
	// Two sonars: one looking forward from (0.1, 0), one looking left (+90 deg) from (0, 0.1).
	mrpt::obs::CObservationRange::TMeasurement fwd, left;
	fwd.sensorID = 3;
	fwd.sensorPose = {0.1, 0.0, 0.0, 0.0, 0.0, 0.0};
	fwd.sensedDistance = 1.0f;
	left.sensorID = 0;
	left.sensorPose = {0.0, 0.1, 0.0, M_PI / 2, 0.0, 0.0};
	left.sensedDistance = 2.0f;
	obs.sensedData = {fwd, left};
	CTiledOccupancyGrid grid;
	// Robot at (1.05, 1.05) heading +90 deg: the forward sonar looks along +y
	// from (1.05, 1.15), the left one along -x from (0.95, 1.05).
	const auto stats = CSonarGridInserter().insert(grid, mrpt::poses::CPose2D(1.05, 1.05, M_PI / 2), obs);
	EXPECT_EQ(stats.readings_inserted, 2u);
	EXPECT_GT(grid.occupancyProbability({10, 21}), 0.5);  // echo 1 m ahead at (1.05, 2.15)
	EXPECT_GT(grid.occupancyProbability({-11, 10}), 0.5);  // echo 2 m to the left at (-1.05, 1.05)
	EXPECT_LT(grid.occupancyProbability({0, 10}), 0.5);  // on the left sonar's axis
	EXPECT_FALSE(grid.isObserved({10, 30}));
}

TEST(SonarGridInserter, FusionFavoursTheLaserButGlassStillAppears)
{
	// A glass pane at x = 1.0 m: the laser passes through (its return from the
	// wall 4 m behind is beyond its 3 m range, so it is not inserted); the
	// sonar echoes at 1.0 m. A solid wall at y = 1.0 m is seen by both.
	CTiledOccupancyGrid grid;
	CSonarGridInserter sonar;  // defaults: fast, weight 0.1
	CLaserGridInserter laser;
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.resizeScan(3);  // beams at -90, 0, +90 deg
	const float ranges[3] = {5.0f, 5.0f, 0.97f};  // +90 deg: wall at y = 1.02 (cell 10)
	for (size_t i = 0; i < 3; ++i) scan.setScanRange(i, ranges[i]), scan.setScanRangeValidity(i, true);
	TSonarReading toWall = readingAt1m();
	toWall.sensor.phi = M_PI / 2;
	toWall.range_m = 1.6;  // a specular reading: the sonar claims free space through the wall
	for (int k = 0; k < 20; ++k)
	{
		laser.insert(grid, mrpt::poses::CPose2D(0.05, 0.05, 0), scan);
		sonar.insert(grid, readingAt1m());
		sonar.insert(grid, toWall);
	}
	EXPECT_GT(grid.occupancyProbability({10, 0}), 0.9);  // glass: sonar only, still occupied
	EXPECT_GT(grid.occupancyProbability({0, 10}), 0.9);  // wall: laser wins over the sonar's free axis
}

TEST(SonarGridInserter, OptionsFromIniAndBadModelRejected)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("sonar_model", "model", "standard");
	cfg.write("sonar_model", "default_cone_aperture_deg", "30");
	CSonarGridInserter::TOptions o;
	hslam::common::loadOptions(o, cfg, "sonar_model");
	EXPECT_EQ(o.model, "standard");
	EXPECT_NEAR(o.default_cone_aperture_rad, 30 * M_PI / 180, 1e-12);
	cfg.write("sonar_model", "model", "elfes");
	EXPECT_THROW(hslam::common::loadOptions(o, cfg, "sonar_model"), hslam::common::config_error);
	o.model = "elfes";
	EXPECT_THROW(CSonarGridInserter{o}, std::invalid_argument);
}
