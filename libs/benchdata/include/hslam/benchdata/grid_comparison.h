/* hslam: cell-by-cell comparison of our tiled grid with an MRPT
 * COccupancyGridMap2D (used by benchmarks and tests). Cells are classified as
 * occupied (p_occ > 0.5 + margin), free (p_occ < 0.5 - margin) or unknown;
 * agreement is counted over the cells known in at least one of the two maps. */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>

namespace hslam::benchdata
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
	size_t ours_known = 0;  //!< of those, known in ours (every agreed cell is)
	size_t occupied_both = 0, occupied_only_ours = 0, occupied_only_mrpt = 0;
	double fraction() const { return compared ? static_cast<double>(agreed) / compared : 1.0; }
	/** Agreement over the cells our map claims to know. */
	double fractionOfOursKnown() const { return ours_known ? static_cast<double>(agreed) / ours_known : 1.0; }
	/** Reference occupied cells also occupied in ours. */
	double occupiedFound() const
	{
		const size_t n = occupied_both + occupied_only_mrpt;
		return n ? static_cast<double>(occupied_both) / n : 1.0;
	}
};

/** Compares every cell of `mrptGrid` (which must use the same resolution). */
TCellAgreement compareWithMrptGrid(const maps::CTiledOccupancyGrid& ours, const mrpt::maps::COccupancyGridMap2D& mrptGrid,
								   double margin = 0.01);

/** A reference grid of any resolution in its own frame (e.g. a simulator's
 * ground truth, gt_map.gridmap.gz at 5 cm) resampled onto our cells `cells`
 * (our resolution and cell edges), with our map frame at `oursInReference` in
 * the reference frame. A cell is occupied if any reference sample inside it is
 * occupied (thin walls stay), free if its samples are all free, unknown
 * otherwise; samples every half reference cell. The result can be passed to
 * compareWithMrptGrid. */
mrpt::maps::COccupancyGridMap2D resampleOntoOurCells(const mrpt::maps::COccupancyGridMap2D& reference,
													 const maps::CTiledGridGeometry& ours, const maps::TCellBounds& cells,
													 const mrpt::poses::CPose2D& oursInReference,
													 double margin = 0.01);

}  // namespace hslam::benchdata
