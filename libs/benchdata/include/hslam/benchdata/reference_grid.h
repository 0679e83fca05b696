/* hslam: a reference map (e.g. a simulator's ground truth,
 * gt_map.gridmap.gz at 5 cm) resampled onto our cells, so that it can be
 * scored against our grid cell for cell (map_scoring.h). */
#pragma once

#include <hslam/benchdata/map_scoring.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

namespace hslam::benchdata
{
/** A reference grid of any resolution in its own frame (e.g. a simulator's
 * ground truth, gt_map.gridmap.gz at 5 cm) resampled onto our cells `cells`
 * (our resolution and cell edges), with our map frame at `oursInReference` in
 * the reference frame. A cell is occupied if any reference sample inside it is
 * occupied (thin walls stay), free if its samples are all free, unknown
 * otherwise; samples every half reference cell. The result can be passed to
 * scoreMap (map_scoring.h). */
mrpt::maps::COccupancyGridMap2D resampleOntoOurCells(const mrpt::maps::COccupancyGridMap2D& reference,
													 const maps::CTiledGridGeometry& ours, const maps::TCellBounds& cells,
													 const mrpt::poses::CPose2D& oursInReference,
													 double margin = kClassMargin);

}  // namespace hslam::benchdata
