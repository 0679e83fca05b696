/* hslam: map-versus-reference figures (see map_scoring.h). */
#include <hslam/benchdata/map_scoring.h>

#include <cmath>
#include <stdexcept>

namespace hslam::benchdata
{
namespace
{
/** Is any cell within the tolerance of `c` occupied in `classes`? */
bool occupiedWithinTolerance(const TCellClassOf& classes, const maps::TGlobalCell& c)
{
	constexpr int t = kOccupiedToleranceCells;
	for (int dy = -t; dy <= t; ++dy)
		for (int dx = -t; dx <= t; ++dx)
			if (classes({c.gx + dx, c.gy + dy}) == ECellClass::occupied) return true;
	return false;
}

template <class F>
void forEachCell(const maps::TCellBounds& cells, F&& f)
{
	for (int gy = cells.gyMin; gy <= cells.gyMax; ++gy)
		for (int gx = cells.gxMin; gx <= cells.gxMax; ++gx) f(maps::TGlobalCell{gx, gy});
}
}  // namespace

ECellClass classifyOccupancy(double p, double margin)
{
	if (p > 0.5 + margin) return ECellClass::occupied;
	if (p < 0.5 - margin) return ECellClass::free;
	return ECellClass::unknown;
}

TCellClassOf cellClassesOf(const maps::CTiledOccupancyGrid& grid)
{
	return [&grid](const maps::TGlobalCell& c) {
		return grid.isObserved(c) ? classifyOccupancy(grid.occupancyProbability(c)) : ECellClass::unknown;
	};
}

TCellClassOf cellClassesOf(const mrpt::maps::COccupancyGridMap2D& grid, const maps::CTiledGridGeometry& ours)
{
	return [&grid, ours](const maps::TGlobalCell& c) {
		const auto p = ours.cellCentre(c);
		// floor, not MRPT's x2idx (it truncates: a centre half a cell outside maps to cell 0)
		const int cx = static_cast<int>(std::floor((p.x - grid.getXMin()) / grid.getResolution()));
		const int cy = static_cast<int>(std::floor((p.y - grid.getYMin()) / grid.getResolution()));
		if (cx < 0 || cy < 0 || cx >= static_cast<int>(grid.getSizeX()) || cy >= static_cast<int>(grid.getSizeY()))
			return ECellClass::unknown;
		return classifyOccupancy(1.0 - grid.getCell(cx, cy));  // MRPT stores the probability of FREE
	};
}

maps::TCellBounds cellBoundsOf(const mrpt::maps::COccupancyGridMap2D& grid, const maps::CTiledGridGeometry& ours)
{
	if (grid.getSizeX() == 0 || grid.getSizeY() == 0) return {};
	const auto lo = ours.cellOf(grid.idx2x(0), grid.idx2y(0));
	const auto hi = ours.cellOf(grid.idx2x(grid.getSizeX() - 1), grid.idx2y(grid.getSizeY() - 1));
	return {lo.gx, hi.gx, lo.gy, hi.gy};
}

void TMapScore::add(const TMapScore& o)
{
	compared += o.compared, agreed += o.agreed, ours_known += o.ours_known, ours_occupied += o.ours_occupied;
	false_occupied += o.false_occupied, reference_occupied += o.reference_occupied;
	reference_occupied_found += o.reference_occupied_found;
}

TMapScore scoreMap(const TCellClassOf& ours, const TCellClassOf& reference, const maps::TCellBounds& cells)
{
	TMapScore s;
	forEachCell(cells, [&](const maps::TGlobalCell& c) {
		const ECellClass a = ours(c), b = reference(c);
		if (b == ECellClass::occupied)
		{
			++s.reference_occupied;
			s.reference_occupied_found += occupiedWithinTolerance(ours, c);
		}
		if (a == ECellClass::unknown && b == ECellClass::unknown) return;
		++s.compared;
		s.agreed += a == b;
		if (a == ECellClass::unknown) return;
		++s.ours_known;
		if (a != ECellClass::occupied) return;
		++s.ours_occupied;
		s.false_occupied += !occupiedWithinTolerance(reference, c);
	});
	return s;
}

TMapScore scoreMap(const maps::CTiledOccupancyGrid& ours, const mrpt::maps::COccupancyGridMap2D& reference)
{
	const auto& geometry = ours.geometry();
	if (std::abs(reference.getResolution() - geometry.resolution_m()) > 1e-6)
		throw std::invalid_argument("scoreMap: grids have different resolutions");
	return scoreMap(cellClassesOf(ours), cellClassesOf(reference, geometry), cellBoundsOf(reference, geometry));
}

std::vector<maps::TGlobalCell> falseOccupiedCells(const TCellClassOf& ours, const TCellClassOf& reference,
												  const maps::TCellBounds& cells)
{
	std::vector<maps::TGlobalCell> out;
	forEachCell(cells, [&](const maps::TGlobalCell& c) {
		if (ours(c) == ECellClass::occupied && !occupiedWithinTolerance(reference, c)) out.push_back(c);
	});
	return out;
}

std::vector<maps::TGlobalCell> occupiedCells(const maps::CTiledOccupancyGrid& grid)
{
	std::vector<maps::TGlobalCell> out;
	const TCellClassOf classes = cellClassesOf(grid);
	forEachCell(grid.observedBounds(), [&](const maps::TGlobalCell& c) {
		if (classes(c) == ECellClass::occupied) out.push_back(c);
	});
	return out;
}

}  // namespace hslam::benchdata
