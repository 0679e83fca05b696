/* hslam: counting the cells a map wrongly holds as occupied (the "trail" of
 * walking people), used to measure the effect of dynamic object exclusion
 * (thesis 4.7: dynamic objects must not be written into the map). */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>

#include <vector>

namespace hslam::benchdata
{
/** Observed cells with occupancy probability above `threshold`. */
std::vector<maps::TGlobalCell> occupiedCells(const maps::CTiledOccupancyGrid& grid, double threshold = 0.5);

/** Occupied cells of `grid` farther than `toleranceCells` (Chebyshev
 * distance) from every occupied cell of `reference` (the static structure). */
std::vector<maps::TGlobalCell> cellsNotIn(const maps::CTiledOccupancyGrid& grid,
										  const maps::CTiledOccupancyGrid& reference, int toleranceCells,
										  double threshold = 0.5);

}  // namespace hslam::benchdata
