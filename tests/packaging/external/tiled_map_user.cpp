/* External user of the installed hslam package: MRPT's map factory creates
 * our CTiledOccupancyGridMap2D from its INI name ("tiledOccupancyGrid"), a
 * scan of a wall is inserted, and the result is checked by numbers. Prints
 * what it checked; exit code 0 only when every check holds. */
#include <hslam/maps/CTiledOccupancyGridMap2D.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <iostream>

namespace
{
const char* kMapIni = R"(
[MAPS]
tiledOccupancyGrid_count = 1
[MAPS_tiledOccupancyGrid_00_creationOpts]
resolution_m = 0.05
[MAPS_tiledOccupancyGrid_00_insertOpts]
laser_max_range_m = 10.0
)";

/** 181 beams over 180 deg from the origin facing +x, hitting a wall x = 2 m. */
mrpt::obs::CObservation2DRangeScan wallScan()
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(M_PI);
	scan.rightToLeft = true;
	scan.maxRange = 10.0f;
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		const double angle_rad = -M_PI / 2 + M_PI * i / 180.0;
		const double range_m = std::cos(angle_rad) > 0.25 ? 2.0 / std::cos(angle_rad) : 10.0;
		scan.setScanRange(i, static_cast<float>(std::min(range_m, 10.0)));
		scan.setScanRangeValidity(i, range_m < 10.0);
	}
	return scan;
}

int check(bool ok, const char* what)
{
	std::cout << (ok ? "ok   " : "FAIL ") << what << "\n";
	return ok ? 0 : 1;
}
}  // namespace

int main()
{
	hslam::maps::registerTiledMapClasses();
	mrpt::config::CConfigFileMemory cfg(kMapIni);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(cfg, "MAPS");
	mrpt::maps::CMultiMetricMap multi;
	multi.setListOfMaps(inits);
	const auto map = multi.mapByClass<hslam::maps::CTiledOccupancyGridMap2D>();
	int failures = check(inits.size() == 1 && map != nullptr, "MRPT's factory made a CTiledOccupancyGridMap2D");
	if (!map) return 1;
	failures += check(std::abs(map->grid().options().resolution_m - 0.05) < 1e-12, "resolution_m = 0.05 from the INI");

	const bool inserted = multi.insertObservation(wallScan(), mrpt::poses::CPose3D());
	const auto& grid = map->grid();
	const double wall_p = grid.occupancyProbability(grid.geometry().cellOf(2.01, 0.0));
	const double free_p = grid.occupancyProbability(grid.geometry().cellOf(1.0, 0.0));
	const double behind_p = grid.occupancyProbability(grid.geometry().cellOf(3.0, 0.0));
	std::cout << "p(occupied): wall (2.01, 0) = " << wall_p << ", free (1, 0) = " << free_p
			  << ", behind (3, 0) = " << behind_p << "\n";
	failures += check(inserted, "the scan was inserted");
	failures += check(wall_p > 0.8, "wall cell occupied (p > 0.8)");
	failures += check(free_p < 0.4, "cell between robot and wall free (p < 0.4)");
	failures += check(std::abs(behind_p - 0.5) < 0.05, "cell behind the wall unknown (p = 0.5)");
	return failures == 0 ? 0 : 1;
}
