#include <hslam/maps/CTiledOccupancyGrid.h>
#include <hslam/maps/grid_ray_tracing.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hslam::maps
{
float probabilityToLogOdds(double p) { return static_cast<float>(std::log(p / (1.0 - p))); }
double logOddsToProbability(double logOdds) { return 1.0 / (1.0 + std::exp(-logOdds)); }

CTile::CTile(int sizeCells)
	: m_size(sizeCells), m_cells(static_cast<size_t>(sizeCells) * sizeCells, kUnknownCell)
{
}

size_t CTile::observedCount() const
{
	return m_cells.size() - static_cast<size_t>(std::count(m_cells.begin(), m_cells.end(), kUnknownCell));
}

CTiledOccupancyGrid::CTiledOccupancyGrid(const TOptions& options)
	: m_options(options),
	  m_geometry(options.resolution_m, options.tile_size_cells),
	  m_clampLogOdds(probabilityToLogOdds(options.max_occupied_probability)),
	  m_clampCellUnits(toCellUnits(m_clampLogOdds))
{
	if (!(options.max_occupied_probability > 0.5 && options.max_occupied_probability < 1.0))
		throw std::invalid_argument("CTiledOccupancyGrid: max_occupied_probability must be in (0.5, 1)");
}

CTiledOccupancyGrid::CTiledOccupancyGrid(const CTiledOccupancyGrid& o)
	: m_options(o.m_options),
	  m_geometry(o.m_geometry),
	  m_clampLogOdds(o.m_clampLogOdds),
	  m_clampCellUnits(o.m_clampCellUnits),
	  m_creationOrder(o.m_creationOrder)
{
	for (const auto& kv : o.m_tiles) m_tiles.emplace(kv.first, std::make_unique<CTile>(*kv.second));
}

CTiledOccupancyGrid::CTiledOccupancyGrid(CTiledOccupancyGrid&& o) noexcept
	: m_options(o.m_options),
	  m_geometry(o.m_geometry),
	  m_clampLogOdds(o.m_clampLogOdds),
	  m_clampCellUnits(o.m_clampCellUnits),
	  m_tiles(std::move(o.m_tiles)),
	  m_creationOrder(std::move(o.m_creationOrder))
{
	o.clear();
}

CTiledOccupancyGrid& CTiledOccupancyGrid::operator=(CTiledOccupancyGrid&& o) noexcept
{
	if (this == &o) return *this;
	m_options = o.m_options;
	m_geometry = o.m_geometry;
	m_clampLogOdds = o.m_clampLogOdds;
	m_clampCellUnits = o.m_clampCellUnits;
	m_tiles = std::move(o.m_tiles);
	m_creationOrder = std::move(o.m_creationOrder);
	m_cachedTile = nullptr;
	o.clear();
	return *this;
}

CTiledOccupancyGrid& CTiledOccupancyGrid::operator=(const CTiledOccupancyGrid& o)
{
	if (this != &o) *this = CTiledOccupancyGrid(o);
	return *this;
}

CTile& CTiledOccupancyGrid::tileFor(const TTileIndex& t)
{
	if (m_cachedTile && m_cachedIndex == t) return *m_cachedTile;
	auto it = m_tiles.find(t);
	if (it == m_tiles.end())
	{
		it = m_tiles.emplace(t, std::make_unique<CTile>(m_options.tile_size_cells)).first;
		m_creationOrder.push_back(t);
	}
	m_cachedIndex = t;
	m_cachedTile = it->second.get();
	m_cachedBounds = m_geometry.tileBounds(t);
	return *m_cachedTile;
}

const CTile* CTiledOccupancyGrid::findTile(const TTileIndex& t) const
{
	const auto it = m_tiles.find(t);
	return it == m_tiles.end() ? nullptr : it->second.get();
}

void CTiledOccupancyGrid::updateCell(const TGlobalCell& c, float logOddsDelta)
{
	selectTileOf(c);
	m_cachedTile->update(cachedLocal(c), toCellUnits(logOddsDelta), m_clampCellUnits);
}

size_t CTiledOccupancyGrid::updateRay(const TGlobalCell& from, const TGlobalCell& to, float crossedDelta,
									  float endDelta)
{
	selectTileOf(from);
	if (inCachedTile(to))
		return updateRayInsideTile(*m_cachedTile, cachedLocal(from), cachedLocal(to), toCellUnits(crossedDelta),
								   toCellUnits(endDelta));
	// The ray crosses a tile border: cell by cell, switching tiles as needed.
	size_t cells = 0;
	forEachCellOnSegment(from, to, [&](const TGlobalCell& c) {
		updateCell(c, c == to ? endDelta : crossedDelta);
		++cells;
	});
	return cells;
}

size_t CTiledOccupancyGrid::updateRayInsideTile(CTile& tile, const TLocalCell& a, const TLocalCell& b,
												int crossedDelta, int endDelta)
{
	// Bresenham on the tile's row-major arrays, stepping the linear index.
	const int n = tile.size();
	TLogOddsCell* data = tile.data();
	const int clampValue = m_clampCellUnits;
	const int dx = std::abs(b.lx - a.lx), dy = -std::abs(b.ly - a.ly);
	const int stepX = a.lx < b.lx ? 1 : -1, stepY = a.ly < b.ly ? n : -n;
	int err = dx + dy;
	int index = a.ly * n + a.lx;
	const int endIndex = b.ly * n + b.lx;
	size_t cells = 1;
	for (; index != endIndex; ++cells)
	{
		CTile::add(data[index], crossedDelta, clampValue);
		const int e2 = 2 * err;
		if (e2 >= dy)
		{
			err += dy;
			index += stepX;
		}
		if (e2 <= dx)
		{
			err += dx;
			index += stepY;
		}
	}
	CTile::add(data[endIndex], endDelta, clampValue);
	return cells;
}

float CTiledOccupancyGrid::logOdds(const TGlobalCell& c) const
{
	const CTile* tile = findTile(m_geometry.tileOf(c));
	return tile ? tile->logOdds(m_geometry.localCellOf(c)) : 0.0f;
}

double CTiledOccupancyGrid::occupancyProbability(const TGlobalCell& c) const { return logOddsToProbability(logOdds(c)); }

TLogOddsCell CTiledOccupancyGrid::rawCell(const TGlobalCell& c) const
{
	const CTile* tile = findTile(m_geometry.tileOf(c));
	return tile ? tile->raw(m_geometry.localCellOf(c)) : kUnknownCell;
}

void CTiledOccupancyGrid::setRawCell(const TGlobalCell& c, TLogOddsCell v)
{
	selectTileOf(c);
	m_cachedTile->setRaw(cachedLocal(c), v);
}

bool CTiledOccupancyGrid::isObserved(const TGlobalCell& c) const
{
	const CTile* tile = findTile(m_geometry.tileOf(c));
	return tile && tile->observed(m_geometry.localCellOf(c));
}

TCellBounds CTiledOccupancyGrid::tileExtent() const
{
	TCellBounds b;
	for (const auto& t : m_creationOrder) b.include(m_geometry.tileBounds(t));
	return b;
}

TCellBounds CTiledOccupancyGrid::observedBounds() const
{
	TCellBounds b;
	const int n = m_options.tile_size_cells;
	for (const auto& t : m_creationOrder)
	{
		const CTile& tile = *m_tiles.at(t);
		for (int ly = 0; ly < n; ++ly)
			for (int lx = 0; lx < n; ++lx)
			{
				if (!tile.observed({lx, ly})) continue;
				const TGlobalCell g = m_geometry.globalCellOf(t, {lx, ly});
				b.include({g.gx, g.gx, g.gy, g.gy});
			}
	}
	return b;
}

size_t CTiledOccupancyGrid::memoryBytes() const
{
	size_t bytes = 0;
	for (const auto& kv : m_tiles) bytes += kv.second->memoryBytes();
	return bytes;
}

void CTiledOccupancyGrid::clear()
{
	m_tiles.clear();
	m_creationOrder.clear();
	m_cachedTile = nullptr;
}

}  // namespace hslam::maps
