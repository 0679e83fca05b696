/* hslam sim: ground-truth outputs of a scene that are images/maps (no file
 * I/O here): the static world rasterised as an MRPT occupancy grid (for
 * map-quality scoring against SLAM maps) and an overview picture with the
 * robot path, the odometry path, people tracks and the true corners. */
#pragma once

#include <hslam/sim/scene.h>
#include <mrpt/img/CImage.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <vector>

namespace hslam::sim
{
/** Static world as a grid (p(free) = 1 for free, 0 for occupied) covering the
 * world's bounds plus `margin_m`. Cells a wall passes through or whose area a
 * circle overlaps are occupied; people are not in the map. */
mrpt::maps::COccupancyGridMap2D rasterizeWorld(const CWorld& world, double resolution_m, double margin_m);

struct TOverviewTracks
{
	std::vector<mrpt::math::TPose2D> true_path, odometry_path;
	std::vector<std::vector<mrpt::math::TPoint2D>> people;  //!< body track per person
	std::vector<TWorldCorner> corners;
};

/** Picture of the grid with the tracks: true path red, odometry blue, people
 * in green/orange/purple..., corners as small squares (concave magenta,
 * convex cyan). About `maxSidePx` pixels on the longer side. */
mrpt::img::CImage renderOverview(const mrpt::maps::COccupancyGridMap2D& grid, const TOverviewTracks& tracks,
								 int maxSidePx = 1000);

}  // namespace hslam::sim
