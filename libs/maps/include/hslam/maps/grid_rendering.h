/* hslam: turning the tiled grid into things people and MRPT tools can open:
 * colour images (unknown cells in a distinct blue-grey, observed cells in grey
 * levels from white = free to black = occupied) with trajectories drawn on
 * them, and a merged mrpt::maps::COccupancyGridMap2D. No file I/O here. */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/img/CImage.h>
#include <mrpt/img/TColor.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <vector>

namespace hslam::maps
{
/** Maps world coordinates to pixels of an image of a block of cells
 * (north up: the top row is the largest y). */
struct TImageFrame
{
	TCellBounds cells;
	double resolution_m = 0.1;
	int pixels_per_cell = 1;

	int widthPx() const { return cells.width() * pixels_per_cell; }
	int heightPx() const { return cells.height() * pixels_per_cell; }
	/** Pixel (column, row) of a world point, as doubles (centre of a cell = .5). */
	void worldToPixel(double x_m, double y_m, double& col, double& row) const;
};

/** Colour used for never-observed cells. */
constexpr mrpt::img::TColor kUnknownCellColour{170, 185, 205};

/** Renders the given block of cells. */
mrpt::img::CImage renderGrid(const CTiledOccupancyGrid& grid, const TImageFrame& frame);

/** Frame covering the observed cells plus a margin (cells); a small default
 * frame around the origin if nothing was observed. */
TImageFrame frameForObservedArea(const CTiledOccupancyGrid& grid, int marginCells, int pixelsPerCell);

/** Frame covering exactly one tile. */
TImageFrame frameForTile(const CTiledOccupancyGrid& grid, const TTileIndex& tile, int pixelsPerCell);

/** Draws a polyline through the poses' positions. */
void drawTrajectory(mrpt::img::CImage& image, const TImageFrame& frame, const std::vector<mrpt::math::TPose2D>& poses,
					const mrpt::img::TColor& colour, unsigned widthPx = 1);

/** A plain MRPT grid with the same cells (same resolution and cell centres;
 * unknown cells stay at 0.5). MRPT stores the probability of FREE. */
mrpt::maps::COccupancyGridMap2D toMrptGrid(const CTiledOccupancyGrid& grid, const TCellBounds& cells);

}  // namespace hslam::maps
