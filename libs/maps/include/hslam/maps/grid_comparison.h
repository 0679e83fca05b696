/* hslam: cell-by-cell comparison of our tiled grid with an MRPT
 * COccupancyGridMap2D (used by benchmarks and tests). Cells are classified as
 * occupied (p_occ > 0.5 + margin), free (p_occ < 0.5 - margin) or unknown;
 * agreement is counted over the cells known in at least one of the two maps. */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cstddef>

namespace hslam::maps
{
enum class ECellClass
{
	unknown,
	free,
	occupied
};

ECellClass classifyOccupancy(double occupancyProbability, double margin);

struct TCellAgreement
{
	size_t compared = 0;  //!< cells known in at least one map
	size_t agreed = 0;  //!< of those, same class in both
	size_t occupied_both = 0, occupied_only_ours = 0, occupied_only_mrpt = 0;
	double fraction() const { return compared ? static_cast<double>(agreed) / compared : 1.0; }
};

/** Compares every cell of `mrptGrid` (which must use the same resolution). */
TCellAgreement compareWithMrptGrid(const CTiledOccupancyGrid& ours, const mrpt::maps::COccupancyGridMap2D& mrptGrid,
								   double margin = 0.01);

}  // namespace hslam::maps
