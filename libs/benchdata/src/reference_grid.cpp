/* hslam: a reference map resampled onto our cells (see reference_grid.h). */
#include <hslam/benchdata/reference_grid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hslam::benchdata
{
mrpt::maps::COccupancyGridMap2D resampleOntoOurCells(const mrpt::maps::COccupancyGridMap2D& reference,
													 const maps::CTiledGridGeometry& ours, const maps::TCellBounds& cells,
													 const mrpt::poses::CPose2D& oursInReference, double margin)
{
	const double res = ours.resolution_m();
	mrpt::maps::COccupancyGridMap2D out;
	if (cells.empty()) return out;
	// Limits are multiples of res: MRPT keeps them, so cell edges coincide.
	out.setSize(cells.gxMin * res, (cells.gxMax + 1) * res, cells.gyMin * res, (cells.gyMax + 1) * res,
				static_cast<float>(res), 0.5f);
	const int samples = std::max(1, static_cast<int>(std::ceil(2.0 * res / reference.getResolution())));
	const double step = res / samples;
	for (unsigned cy = 0; cy < out.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < out.getSizeX(); ++cx)
		{
			const double x0 = out.idx2x(cx) - 0.5 * res, y0 = out.idx2y(cy) - 0.5 * res;
			bool anyOccupied = false, anyUnknown = false;
			for (int j = 0; j < samples && !anyOccupied; ++j)
				for (int i = 0; i < samples && !anyOccupied; ++i)
				{
					double xr, yr;
					oursInReference.composePoint(x0 + (i + 0.5) * step, y0 + (j + 0.5) * step, xr, yr);
					const int rx = reference.x2idx(xr), ry = reference.y2idx(yr);
					if (rx < 0 || ry < 0 || rx >= static_cast<int>(reference.getSizeX()) ||
						ry >= static_cast<int>(reference.getSizeY()))
					{
						anyUnknown = true;
						continue;
					}
					const ECellClass c = classifyOccupancy(1.0 - reference.getCell(rx, ry), margin);
					anyOccupied = c == ECellClass::occupied;
					anyUnknown |= c == ECellClass::unknown;
				}
			// MRPT stores the probability of FREE.
			out.setCell(cx, cy, anyOccupied ? 0.02f : (anyUnknown ? 0.5f : 0.98f));
		}
	return out;
}

}  // namespace hslam::benchdata
