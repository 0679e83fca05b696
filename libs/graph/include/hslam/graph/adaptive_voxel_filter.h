/* hslam graph: the adaptive voxel filter of a query scan (Hess et al., ICRA
 * 2016, section IV; Cartographer's AdaptiveVoxelFilter): the coarsest voxel
 * grid, up to a maximum cell size, that still leaves a minimum number of
 * points. A scan's near walls are sampled far more densely than its far ones;
 * thinning them costs the correlative search little information but divides
 * its cost (every node of branch-and-bound scores every query point). */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace hslam::graph
{
/** The first point of each square cell of `cell_m` (cells aligned at 0). */
std::vector<mrpt::math::TPoint2Df> voxelFilter(const std::vector<mrpt::math::TPoint2Df>& points, double cell_m);

/** voxelFilter with the largest cell in (0, maxCell_m] (found to within 10 %)
 * that keeps at least minPoints points; all points when there are no more than
 * minPoints or minPoints is 0. */
std::vector<mrpt::math::TPoint2Df> adaptiveVoxelFilter(const std::vector<mrpt::math::TPoint2Df>& points,
														size_t minPoints, double maxCell_m);
}  // namespace hslam::graph
