#include <hslam/benchdata/occupied_cells.h>

#include <cmath>

namespace hslam::benchdata
{
std::vector<maps::TGlobalCell> occupiedCells(const maps::CTiledOccupancyGrid& grid, double threshold)
{
	std::vector<maps::TGlobalCell> out;
	const auto b = grid.observedBounds();
	for (int gy = b.gyMin; gy <= b.gyMax; ++gy)
		for (int gx = b.gxMin; gx <= b.gxMax; ++gx)
		{
			const maps::TGlobalCell c{gx, gy};
			if (grid.isObserved(c) && grid.occupancyProbability(c) > threshold) out.push_back(c);
		}
	return out;
}

std::vector<maps::TGlobalCell> cellsNotIn(const maps::CTiledOccupancyGrid& grid,
										  const maps::CTiledOccupancyGrid& reference, int toleranceCells,
										  double threshold)
{
	std::vector<maps::TGlobalCell> out;
	for (const auto& c : occupiedCells(grid, threshold))
	{
		bool near = false;
		for (int dy = -toleranceCells; dy <= toleranceCells && !near; ++dy)
			for (int dx = -toleranceCells; dx <= toleranceCells && !near; ++dx)
			{
				const maps::TGlobalCell r{c.gx + dx, c.gy + dy};
				near = reference.isObserved(r) && reference.occupancyProbability(r) > threshold;
			}
		if (!near) out.push_back(c);
	}
	return out;
}

}  // namespace hslam::benchdata
