#include <hslam/maps/CTiledGridGeometry.h>

#include <cmath>
#include <stdexcept>

namespace hslam::maps
{
CTiledGridGeometry::CTiledGridGeometry(double resolution_m, int tileSizeCells)
	: m_resolution_m(resolution_m), m_inverseResolution(1.0 / resolution_m), m_tileSizeCells(tileSizeCells), m_half(tileSizeCells / 2)
{
	if (!(resolution_m > 0) || tileSizeCells < 2)
		throw std::invalid_argument("CTiledGridGeometry: resolution must be > 0 and tiles at least 2 cells wide");
}

mrpt::math::TPoint2D CTiledGridGeometry::cellCentre(const TGlobalCell& c) const
{
	return {(c.gx + 0.5) * m_resolution_m, (c.gy + 0.5) * m_resolution_m};
}

TTileIndex CTiledGridGeometry::tileOf(const TGlobalCell& c) const
{
	return {floorDiv(c.gx + m_half, m_tileSizeCells), floorDiv(c.gy + m_half, m_tileSizeCells)};
}

TLocalCell CTiledGridGeometry::localCellOf(const TGlobalCell& c) const
{
	const TTileIndex t = tileOf(c);
	return {c.gx + m_half - t.ix * m_tileSizeCells, c.gy + m_half - t.iy * m_tileSizeCells};
}

TGlobalCell CTiledGridGeometry::globalCellOf(const TTileIndex& t, const TLocalCell& l) const
{
	return {t.ix * m_tileSizeCells + l.lx - m_half, t.iy * m_tileSizeCells + l.ly - m_half};
}

TCellBounds CTiledGridGeometry::tileBounds(const TTileIndex& t) const
{
	const TGlobalCell lo = globalCellOf(t, {0, 0});
	return {lo.gx, lo.gx + m_tileSizeCells - 1, lo.gy, lo.gy + m_tileSizeCells - 1};
}

}  // namespace hslam::maps
