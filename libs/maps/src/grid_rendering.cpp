#include <hslam/maps/grid_rendering.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hslam::maps
{
namespace
{
/** Grey level of each raw cell value (white = free, black = occupied),
 * computed once per distinct value: a map holds a few thousand distinct
 * values in millions of cells. */
class CGreyLevels
{
   public:
	uint8_t operator()(TLogOddsCell raw)
	{
		int16_t& grey = m_grey[static_cast<uint16_t>(raw)];
		if (grey < 0)  // as CTiledOccupancyGrid::occupancyProbability() computes it
		{
			const float logOdds = static_cast<float>(raw) / kLogOddsScale;
			grey = static_cast<int16_t>(std::lround(255.0 * (1.0 - logOddsToProbability(logOdds))));
		}
		return static_cast<uint8_t>(grey);
	}

   private:
	std::vector<int16_t> m_grey = std::vector<int16_t>(1 << 16, -1);
};

/** Paints the k x k pixels of cell (gx, gy). Pixels in memory are B, G, R
 * (what CImage::setPixel writes for 0xRRGGBB). */
void paintCell(mrpt::img::CImage& image, const TImageFrame& frame, int gx, int gy, const uint8_t bgr[3])
{
	const int k = frame.pixels_per_cell;
	const int col0 = (gx - frame.cells.gxMin) * k, row0 = (frame.cells.gyMax - gy) * k;
	for (int dy = 0; dy < k; ++dy)
	{
		uint8_t* pixel = image.ptr<uint8_t>(static_cast<unsigned>(col0), static_cast<unsigned>(row0 + dy));
		for (int dx = 0; dx < k; ++dx, pixel += 3) std::copy(bgr, bgr + 3, pixel);
	}
}

void fillUnknown(mrpt::img::CImage& image, const TImageFrame& frame)
{
	const uint8_t bgr[3] = {kUnknownCellColour.B, kUnknownCellColour.G, kUnknownCellColour.R};
	for (int row = 0; row < frame.heightPx(); ++row)
	{
		uint8_t* pixel = image.ptr<uint8_t>(0, static_cast<unsigned>(row));
		for (int col = 0; col < frame.widthPx(); ++col, pixel += 3) std::copy(bgr, bgr + 3, pixel);
	}
}

/** The cells of `bounds` shared with `frame` (empty if none). */
TCellBounds overlap(const TCellBounds& bounds, const TCellBounds& frame)
{
	return {std::max(bounds.gxMin, frame.gxMin), std::min(bounds.gxMax, frame.gxMax), std::max(bounds.gyMin, frame.gyMin),
			std::min(bounds.gyMax, frame.gyMax)};
}
}  // namespace

void TImageFrame::worldToPixel(double x_m, double y_m, double& col, double& row) const
{
	// Cell g spans [g res, (g + 1) res); cell gxMin starts at column 0, row 0 is gyMax.
	col = (x_m / resolution_m - cells.gxMin) * pixels_per_cell;
	row = (cells.gyMax + 1 - y_m / resolution_m) * pixels_per_cell;
}

mrpt::img::CImage renderGrid(const CTiledOccupancyGrid& grid, const TImageFrame& frame)
{
	mrpt::img::CImage image(frame.widthPx(), frame.heightPx(), mrpt::img::CH_RGB);
	fillUnknown(image, frame);
	// Tile by tile rather than cell by cell through the tile lookup: the
	// observed cells are painted over the unknown colour (same pixels).
	CGreyLevels greyOf;
	const auto& geometry = grid.geometry();
	for (const TTileIndex& t : grid.tilesInCreationOrder())
	{
		const TCellBounds cells = overlap(geometry.tileBounds(t), frame.cells);
		const CTile* tile = cells.empty() ? nullptr : grid.findTile(t);
		if (!tile) continue;
		for (int gy = cells.gyMin; gy <= cells.gyMax; ++gy)
			for (int gx = cells.gxMin; gx <= cells.gxMax; ++gx)
			{
				const TLogOddsCell raw = tile->raw(geometry.localCellOf({gx, gy}));
				if (raw == kUnknownCell) continue;
				const uint8_t grey = greyOf(raw), bgr[3] = {grey, grey, grey};
				paintCell(image, frame, gx, gy, bgr);
			}
	}
	return image;
}

TImageFrame frameForObservedArea(const CTiledOccupancyGrid& grid, int marginCells, int pixelsPerCell)
{
	TImageFrame frame;
	frame.resolution_m = grid.geometry().resolution_m();
	frame.pixels_per_cell = pixelsPerCell;
	TCellBounds b = grid.observedBounds();
	if (b.empty()) b = {-10, 10, -10, 10};
	frame.cells = {b.gxMin - marginCells, b.gxMax + marginCells, b.gyMin - marginCells, b.gyMax + marginCells};
	return frame;
}

TImageFrame frameForTile(const CTiledOccupancyGrid& grid, const TTileIndex& tile, int pixelsPerCell)
{
	TImageFrame frame;
	frame.resolution_m = grid.geometry().resolution_m();
	frame.pixels_per_cell = pixelsPerCell;
	frame.cells = grid.geometry().tileBounds(tile);
	return frame;
}

void drawTrajectory(mrpt::img::CImage& image, const TImageFrame& frame, const std::vector<mrpt::math::TPose2D>& poses,
					const mrpt::img::TColor& colour, unsigned widthPx)
{
	for (size_t i = 1; i < poses.size(); ++i)
	{
		double c0, r0, c1, r1;
		frame.worldToPixel(poses[i - 1].x, poses[i - 1].y, c0, r0);
		frame.worldToPixel(poses[i].x, poses[i].y, c1, r1);
		image.line(static_cast<int>(c0), static_cast<int>(r0), static_cast<int>(c1), static_cast<int>(r1), colour,
				   widthPx);
	}
	if (!poses.empty())
	{
		double c, r;
		frame.worldToPixel(poses.front().x, poses.front().y, c, r);
		image.drawCircle(static_cast<int>(c), static_cast<int>(r), 4, colour, 2);  // start marker
	}
}

mrpt::maps::COccupancyGridMap2D toMrptGrid(const CTiledOccupancyGrid& grid, const TCellBounds& cells)
{
	const double res = grid.geometry().resolution_m();
	// MRPT cell cx spans [xMin + cx res, xMin + (cx+1) res) with xMin rounded to
	// a multiple of res, like our cell edges: the cells coincide one to one.
	mrpt::maps::COccupancyGridMap2D out(
		static_cast<float>(cells.gxMin * res), static_cast<float>((cells.gxMax + 1) * res),
		static_cast<float>(cells.gyMin * res), static_cast<float>((cells.gyMax + 1) * res), static_cast<float>(res));
	for (int gy = cells.gyMin; gy <= cells.gyMax; ++gy)
		for (int gx = cells.gxMin; gx <= cells.gxMax; ++gx)
		{
			if (!grid.isObserved({gx, gy})) continue;
			const int cx = out.x2idx((gx + 0.5) * res), cy = out.y2idx((gy + 0.5) * res);
			if (cx < 0 || cy < 0 || cx >= static_cast<int>(out.getSizeX()) || cy >= static_cast<int>(out.getSizeY()))
				continue;
			out.setCell(cx, cy, static_cast<float>(1.0 - grid.occupancyProbability({gx, gy})));
		}
	return out;
}

}  // namespace hslam::maps
