#include <hslam/maps/grid_comparison.h>

#include <cmath>
#include <stdexcept>

namespace hslam::maps
{
ECellClass classifyOccupancy(double p, double margin)
{
	if (p > 0.5 + margin) return ECellClass::occupied;
	if (p < 0.5 - margin) return ECellClass::free;
	return ECellClass::unknown;
}

TCellAgreement compareWithMrptGrid(const CTiledOccupancyGrid& ours, const mrpt::maps::COccupancyGridMap2D& mrptGrid,
								   double margin)
{
	const double res = ours.geometry().resolution_m();
	if (std::abs(mrptGrid.getResolution() - res) > 1e-6)
		throw std::invalid_argument("compareWithMrptGrid: grids have different resolutions");
	TCellAgreement out;
	for (unsigned cy = 0; cy < mrptGrid.getSizeY(); ++cy)
		for (unsigned cx = 0; cx < mrptGrid.getSizeX(); ++cx)
		{
			const double x = mrptGrid.idx2x(cx), y = mrptGrid.idx2y(cy);  // cell centre
			const TGlobalCell g = ours.geometry().cellOf(x, y);
			const ECellClass a = ours.isObserved(g) ? classifyOccupancy(ours.occupancyProbability(g), margin)
													: ECellClass::unknown;
			const ECellClass b = classifyOccupancy(1.0 - mrptGrid.getCell(cx, cy), margin);
			if (a == ECellClass::unknown && b == ECellClass::unknown) continue;
			++out.compared;
			if (a == b) ++out.agreed;
			if (a == ECellClass::occupied && b == ECellClass::occupied) ++out.occupied_both;
			if (a == ECellClass::occupied && b != ECellClass::occupied) ++out.occupied_only_ours;
			if (a != ECellClass::occupied && b == ECellClass::occupied) ++out.occupied_only_mrpt;
		}
	return out;
}

}  // namespace hslam::maps
