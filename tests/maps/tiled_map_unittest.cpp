#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/maps/CTiledOccupancyGridMap2D.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstring>
#include <iostream>

using namespace hslam::maps;

namespace
{
/** A 181-beam 180 deg scan taken at `pose` inside an axis-aligned corridor
 * (walls at y = +-halfWidth when alongX, else x = +-halfWidth), exact geometry. */
mrpt::obs::CObservation2DRangeScan corridorScan(const mrpt::poses::CPose2D& pose, double halfWidth, bool alongX)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 30.0f;
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		const double a = pose.phi() - M_PI / 2 + M_PI * i / 180.0;
		const double across = alongX ? std::sin(a) : std::cos(a);
		const double offset = alongX ? pose.y() : pose.x();
		double r = 30.0;
		if (across > 1e-6) r = (halfWidth - offset) / across;
		if (across < -1e-6) r = (-halfWidth - offset) / across;
		scan.setScanRange(i, static_cast<float>(std::min(r, 30.0)));
		scan.setScanRangeValidity(i, r < 30.0);
	}
	return scan;
}

void insertCorridor(CTiledOccupancyGridMap2D& map, double from, double to, bool alongX)
{
	for (double s = from; s <= to; s += 0.5)
	{
		const mrpt::poses::CPose2D pose = alongX ? mrpt::poses::CPose2D(s, 0.0, 0.0) : mrpt::poses::CPose2D(0.0, s, M_PI / 2);
		map.insertObservation(corridorScan(pose, 1.0, alongX), mrpt::poses::CPose3D(pose));
	}
}

const char* kMapIni = R"(
[MAPS]
tiledOccupancyGrid_count = 1
[MAPS_tiledOccupancyGrid_00_creationOpts]
resolution_m = 0.05
tile_size_cells = 100
enableSaveAs3DObject = false
[MAPS_tiledOccupancyGrid_00_insertOpts]
laser_max_range_m = 4.0
sonar_model = standard
sonar_weight = 0.3
[MAPS_tiledOccupancyGrid_00_likelihoodOpts]
sigma_m = 0.2
decimation = 2
)";

void expectSameMaps(const CTiledOccupancyGridMap2D& a, const CTiledOccupancyGridMap2D& b)
{
	EXPECT_EQ(a.optionsAsIni(), b.optionsAsIni());
	ASSERT_EQ(a.grid().tilesInCreationOrder().size(), b.grid().tilesInCreationOrder().size());
	const int n = a.grid().options().tile_size_cells;
	for (size_t i = 0; i < a.grid().tilesInCreationOrder().size(); ++i)
	{
		const TTileIndex t = a.grid().tilesInCreationOrder()[i];
		EXPECT_EQ(t, b.grid().tilesInCreationOrder()[i]);
		ASSERT_NE(b.grid().findTile(t), nullptr);
		EXPECT_EQ(0, std::memcmp(a.grid().findTile(t)->data(), b.grid().findTile(t)->data(),
								 sizeof(TLogOddsCell) * n * n));
	}
}
}  // namespace

TEST(TiledMap, MrptCreatesTheMapFromAnIniDefinition)
{
	registerTiledMapClasses();
	mrpt::config::CConfigFileMemory cfg(kMapIni);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(cfg, "MAPS");
	ASSERT_EQ(inits.size(), 1u);
	mrpt::maps::CMultiMetricMap multi;
	multi.setListOfMaps(inits);
	const auto map = multi.mapByClass<CTiledOccupancyGridMap2D>();
	ASSERT_TRUE(map);
	EXPECT_DOUBLE_EQ(map->grid().options().resolution_m, 0.05);
	EXPECT_EQ(map->grid().options().tile_size_cells, 100);
	EXPECT_DOUBLE_EQ(map->insertionOptions.laser.max_range_m, 4.0);
	EXPECT_EQ(map->insertionOptions.sonar.model, "standard");
	EXPECT_DOUBLE_EQ(map->insertionOptions.sonar.weight, 0.3);
	EXPECT_DOUBLE_EQ(map->likelihoodOptions.sigma_m, 0.2);
	EXPECT_EQ(map->likelihoodOptions.decimation, 2);
	EXPECT_FALSE(map->genericMapParams.enableSaveAs3DObject);
	// Inserting through the multi-map reaches our map.
	const mrpt::poses::CPose2D pose(0, 0, 0);
	multi.insertObservation(corridorScan(pose, 1.0, true), mrpt::poses::CPose3D(pose));
	EXPECT_GT(map->grid().occupancyProbability(map->grid().geometry().cellOf(0.5, 1.01)), 0.8);
	EXPECT_LT(map->grid().occupancyProbability(map->grid().geometry().cellOf(0.5, 0.5)), 0.4);
	// A sonar observation goes through the configured (standard) sonar model.
	mrpt::obs::CObservationRange sonar;
	sonar.sensorConeApperture = static_cast<float>(20 * M_PI / 180);
	mrpt::obs::CObservationRange::TMeasurement m;
	m.sensorPose = {0.0, 0.0, 0.0, -M_PI / 2, 0.0, 0.0};  // looking at -y
	m.sensedDistance = 2.0f;
	sonar.sensedData.push_back(m);
	const auto before = map->grid().logOdds(map->grid().geometry().cellOf(0.1, -2.0));
	EXPECT_TRUE(map->insertObservation(sonar, mrpt::poses::CPose3D(0.025, 0.025, 0, 0, 0, 0)));
	EXPECT_NEAR(map->grid().logOdds(map->grid().geometry().cellOf(0.1, -2.0)) - before,
				0.3 * std::log(map->insertionOptions.sonar.max_occupied_probability / 0.02), 1.5);
	EXPECT_GT(map->grid().logOdds(map->grid().geometry().cellOf(0.1, -2.0)), 0.3);
}

TEST(TiledMap, IniDefinitionWithUnknownKeyNamesIt)
{
	registerTiledMapClasses();
	std::string ini = kMapIni;
	ini += "[MAPS_tiledOccupancyGrid_00_insertOpts]\nsonar_wieght = 0.3\n";
	mrpt::config::CConfigFileMemory cfg(ini);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	try
	{
		inits.loadFromConfigFile(cfg, "MAPS");
		FAIL() << "unknown key accepted";
	}
	catch (const std::exception& e)  // MRPT re-wraps our config_error; the message is kept
	{
		EXPECT_NE(std::string(e.what()).find("sonar_wieght"), std::string::npos) << e.what();
	}
}

TEST(TiledMap, SavedMapReloadsIdentically)
{
	CTiledOccupancyGridMap2D map;
	map.insertionOptions.sonar.model = "standard";
	map.likelihoodOptions.sigma_m = 0.15;
	insertCorridor(map, -15.0, 15.0, true);
	ASSERT_GE(map.grid().tileCount(), 3u);

	hslam::testing::CTempDir dir;
	const std::string file = dir.file("map.gz");
	{
		mrpt::io::CFileGZOutputStream out(file);
		mrpt::serialization::archiveFrom(out) << map;
	}
	mrpt::io::CFileGZInputStream in(file);
	const auto obj = mrpt::serialization::archiveFrom(in).ReadObject();
	const auto loaded = std::dynamic_pointer_cast<CTiledOccupancyGridMap2D>(obj);
	ASSERT_TRUE(loaded);
	expectSameMaps(map, *loaded);
	EXPECT_EQ(loaded->insertionOptions.sonar.model, "standard");
	EXPECT_DOUBLE_EQ(loaded->likelihoodOptions.sigma_m, 0.15);
	// The clone (CSerializable::clone, deep copy) is identical too.
	const std::unique_ptr<mrpt::rtti::CObject> clone(map.clone());
	const auto* cloned = dynamic_cast<const CTiledOccupancyGridMap2D*>(clone.get());
	ASSERT_NE(cloned, nullptr);
	expectSameMaps(map, *cloned);
}

TEST(TiledMap, CorruptStreamIsAnErrorNotACrash)
{
	CTiledOccupancyGridMap2D map;
	insertCorridor(map, 0.0, 3.0, true);
	mrpt::io::CMemoryStream buf;
	mrpt::serialization::archiveFrom(buf) << map;
	buf.Seek(0);
	mrpt::io::CMemoryStream truncated;
	std::vector<uint8_t> bytes(buf.getTotalBytesCount() / 2);
	buf.Read(bytes.data(), bytes.size());
	truncated.Write(bytes.data(), bytes.size());
	truncated.Seek(0);
	EXPECT_ANY_THROW(mrpt::serialization::archiveFrom(truncated).ReadObject());
}

TEST(TiledMap, MergedViewMatchesTheTiles)
{
	CTiledOccupancyGridMap2D map;
	insertCorridor(map, -12.0, 12.0, true);  // crosses the tile borders at +-10 m
	const auto merged = map.getAsMrptGrid();
	const hslam::benchdata::TMapScore agreement = hslam::benchdata::scoreMap(map.grid(), merged);
	EXPECT_GT(agreement.compared, 4000u);
	EXPECT_EQ(agreement.agreed, agreement.compared);
	// MRPT stores p(free): a wall cell is dark, the corridor middle light.
	EXPECT_LT(merged.getPos(11.5, 1.01), 0.2);
	EXPECT_GT(merged.getPos(-11.5, 0.0), 0.8);
}

TEST(TiledMap, LikelihoodPeaksAtTheTruePose)
{
	CTiledOccupancyGridMap2D map;
	insertCorridor(map, -2.0, 2.0, true);
	const mrpt::poses::CPose2D truth(0.25, 0.2, 0.0);
	const auto scan = corridorScan(truth, 1.0, true);
	const double atTruth = map.computeObservationLikelihood(scan, mrpt::poses::CPose3D(truth));
	for (const auto& off : {mrpt::poses::CPose2D(0, 0.15, 0), mrpt::poses::CPose2D(0, -0.15, 0),
							mrpt::poses::CPose2D(0, 0, 0.1)})
	{
		const double shifted = map.computeObservationLikelihood(scan, mrpt::poses::CPose3D(truth + off));
		EXPECT_GT(atTruth, shifted + 1.0) << off;
	}
	EXPECT_TRUE(map.canComputeObservationLikelihood(scan));
	EXPECT_FALSE(map.canComputeObservationLikelihood(mrpt::obs::CObservationRange()));
}

TEST(TiledMap, SparseLargeBuildingAllocatesOnlyTouchedTiles)
{
	// A 200 m x 200 m building explored along three long corridors (two along
	// x at y = 0 and y = 60, one along y at x = 0), 3 m laser range.
	CTiledOccupancyGridMap2D map;
	insertCorridor(map, -95.0, 95.0, true);
	insertCorridor(map, -95.0, 95.0, false);
	for (double s = -95.0; s <= 95.0; s += 0.5)
	{
		const mrpt::poses::CPose2D pose(s, 60.0, 0.0);
		auto scan = corridorScan(mrpt::poses::CPose2D(s, 0.0, 0.0), 1.0, true);
		map.insertObservation(scan, mrpt::poses::CPose3D(pose));
	}
	const size_t tiles = map.grid().tileCount();
	const size_t bytes = map.grid().memoryBytes();
	const size_t fullSquareBytes = 2000u * 2000u * sizeof(TLogOddsCell);  // 200 m at 0.1 m, dense int16
	std::cout << "[ sparse map ] tiles=" << tiles << " bytes=" << bytes << " dense_200m_square_bytes=" << fullSquareBytes
			  << "\n";
	// Each corridor crosses 10-11 tiles of 20 m; the square has 100+.
	EXPECT_LE(tiles, 33u);
	EXPECT_GE(tiles, 28u);
	EXPECT_EQ(bytes, tiles * 200u * 200u * sizeof(TLogOddsCell));
	EXPECT_LT(bytes, fullSquareBytes / 3);
}

TEST(TiledMap, MrptCreatesTheMapFromTheShippedIni)
{
	registerTiledMapClasses();
	mrpt::config::CConfigFile cfg(std::string(HSLAM_SOURCE_DIR) + "/config_ini/tiled-map-mrpt.ini");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(cfg, "MappingApplication");
	mrpt::maps::CMultiMetricMap multi;
	multi.setListOfMaps(inits);
	const auto map = multi.mapByClass<CTiledOccupancyGridMap2D>();
	ASSERT_TRUE(map);
	// The shipped file states the defaults: the created map equals a default one.
	EXPECT_EQ(map->optionsAsIni(), CTiledOccupancyGridMap2D().optionsAsIni());
}

// The default INI's [sonar_model] (with the pipeline's `enabled` switch) is
// checked against the options in tests/slam (SonarInBatch.DefaultIniDocumentsTheSonarSections).
