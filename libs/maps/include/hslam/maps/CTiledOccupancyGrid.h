/* hslam: scalable tiled occupancy grid (thesis 4.6.1).
 *
 * The map is a set of N x N tiles created on demand when sensing first reaches
 * them (memory grows with the explored area only), indexed by integer tile
 * coordinates relative to the home tile (0,0); see CTiledGridGeometry for the
 * addressing. Each cell keeps the log-odds of being occupied, so the thesis'
 * Bayes rule (eq. 85) is one addition per update,
 *     l <- l + log(p / (1 - p)),
 * clamped to +-log(Max_occupied / (1 - Max_occupied)) (Max_occupied = 0.98,
 * thesis 4.6.2 iii), which keeps every cell able to change its mind. A cell
 * never updated is "unknown" (distinct from an observed cell at 0.5).
 * Cells are int16 fixed point, 2 bytes each (see CTile). */
#pragma once

#include <hslam/maps/CTiledGridGeometry.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace hslam::maps
{
/** Log-odds are stored like MRPT's COccupancyGridMap2D does: as int16 in
 * fixed point (kLogOddsScale units per nat), 2 bytes per cell; the value
 * kUnknownCell marks a never-observed cell, so no separate observed flag is
 * needed (the foundation used float + flag = 5 B/cell). Quantisation step
 * 0.001 in log-odds is far below any sensor update (|log(0.3/0.7)| = 0.85). */
using TLogOddsCell = int16_t;
constexpr float kLogOddsScale = 1000.0f;
constexpr TLogOddsCell kUnknownCell = INT16_MIN;

inline TLogOddsCell toCellUnits(float logOdds)
{
	const float units = logOdds * kLogOddsScale;  // round half away from zero, inline (std::lround is a libm call)
	return static_cast<TLogOddsCell>(units >= 0 ? units + 0.5f : units - 0.5f);
}

/** Storage of one tile: fixed-point log-odds of occupancy per cell, or
 * kUnknownCell if never observed. */
class CTile
{
   public:
	explicit CTile(int sizeCells);
	/** Raw storage for tight loops: row-major, index = ly * N + lx. */
	TLogOddsCell* data() { return m_cells.data(); }
	const TLogOddsCell* data() const { return m_cells.data(); }
	int size() const { return m_size; }
	/** Log-odds (0 for unknown cells). */
	float logOdds(const TLocalCell& c) const
	{
		const TLogOddsCell v = m_cells[index(c)];
		return v == kUnknownCell ? 0.0f : static_cast<float>(v) / kLogOddsScale;
	}
	bool observed(const TLocalCell& c) const { return m_cells[index(c)] != kUnknownCell; }
	/** Adds `delta` (cell units) to a cell, unknown counting as 0, clamped to +-clamp. */
	static void add(TLogOddsCell& v, int delta, int clamp)
	{
		const int base = (v == kUnknownCell) ? 0 : v;
		v = static_cast<TLogOddsCell>(std::clamp(base + delta, -clamp, clamp));
	}
	void update(const TLocalCell& c, int delta, int clamp) { add(m_cells[index(c)], delta, clamp); }
	/** A cell's raw value (kUnknownCell if never observed). */
	TLogOddsCell raw(const TLocalCell& c) const { return m_cells[index(c)]; }
	/** Sets a cell's raw value (deserialisation). */
	void setRaw(const TLocalCell& c, TLogOddsCell v) { m_cells[index(c)] = v; }
	size_t observedCount() const;
	size_t memoryBytes() const { return m_cells.size() * sizeof(TLogOddsCell); }

   private:
	size_t index(const TLocalCell& c) const { return static_cast<size_t>(c.ly) * m_size + c.lx; }
	int m_size;
	std::vector<TLogOddsCell> m_cells;
};

class CTiledOccupancyGrid
{
   public:
	struct TOptions
	{
		double resolution_m = 0.1;  //!< cell side (m); thesis 4.6.1: 0.1 m
		int tile_size_cells = 200;  //!< N, cells per tile side; thesis: 200 (20 m tiles)
		double max_occupied_probability = 0.98;  //!< clamp, thesis Max_occupied (4.6.2 iii);
												 //!< free side clamped symmetrically at 1 - this

		template <class V>
		void visit(V& v)
		{
			v.real("resolution_m", resolution_m, 0.01, 2.0);
			v.integer("tile_size_cells", tile_size_cells, 10, 4000);
			v.real("max_occupied_probability", max_occupied_probability, 0.51, 0.9999);
		}
	};

	CTiledOccupancyGrid() : CTiledOccupancyGrid(TOptions()) {}
	explicit CTiledOccupancyGrid(const TOptions& options);
	/** Deep copies (MRPT maps must be clonable). */
	CTiledOccupancyGrid(const CTiledOccupancyGrid& o);
	CTiledOccupancyGrid& operator=(const CTiledOccupancyGrid& o);
	/** Moves leave the source empty (its tile cache reset). */
	CTiledOccupancyGrid(CTiledOccupancyGrid&& o) noexcept;
	CTiledOccupancyGrid& operator=(CTiledOccupancyGrid&& o) noexcept;

	const TOptions& options() const { return m_options; }
	const CTiledGridGeometry& geometry() const { return m_geometry; }

	/** Bayes update of one cell with the sensor probability of occupancy p
	 * given as log-odds (thesis eq. 85); creates the tile if needed. */
	void updateCell(const TGlobalCell& c, float logOddsDelta);

	/** Updates the cells on the digital segment from `from` to `to` (both
	 * included): every cell but the last with `crossedDelta`, the last with
	 * `endDelta`. Returns the number of cells updated. Rays inside one tile
	 * (almost all of them) run on the tile's raw storage. */
	size_t updateRay(const TGlobalCell& from, const TGlobalCell& to, float crossedDelta, float endDelta);

	/** Log-odds of occupancy (0 for never-observed cells). */
	float logOdds(const TGlobalCell& c) const;
	/** Probability of occupancy (0.5 for never-observed cells). */
	double occupancyProbability(const TGlobalCell& c) const;
	bool isObserved(const TGlobalCell& c) const;

	size_t tileCount() const { return m_tiles.size(); }
	/** Tiles in creation order (thesis fig. 130: T1 is the home tile...). */
	const std::vector<TTileIndex>& tilesInCreationOrder() const { return m_creationOrder; }
	const CTile* findTile(const TTileIndex& t) const;
	/** Union of the bounds of all existing tiles (empty if none). */
	TCellBounds tileExtent() const;
	/** Bounds of the observed cells only (empty if none). */
	TCellBounds observedBounds() const;
	size_t memoryBytes() const;
	void clear();

	float clampLogOdds() const { return m_clampLogOdds; }
	/** The clamp in cell units (kLogOddsScale per nat). */
	int clampCellUnits() const { return m_clampCellUnits; }

	/** A cell's raw fixed-point value (kUnknownCell if never observed), for
	 * exact bookkeeping of updates (CLaserGridInserter::undo). */
	TLogOddsCell rawCell(const TGlobalCell& c) const;
	/** Sets a cell's raw value (creates its tile if needed). */
	void setRawCell(const TGlobalCell& c, TLogOddsCell v);

	/** Raw access for serialisation: the tile (created if needed). */
	CTile& tileForWriting(const TTileIndex& t) { return tileFor(t); }

   private:
	CTile& tileFor(const TTileIndex& t);
	/** Makes the tile holding `c` the cached one (created if needed). */
	void selectTileOf(const TGlobalCell& c)
	{
		if (!inCachedTile(c)) tileFor(m_geometry.tileOf(c));
	}
	bool inCachedTile(const TGlobalCell& c) const
	{
		return m_cachedTile && c.gx >= m_cachedBounds.gxMin && c.gx <= m_cachedBounds.gxMax &&
			   c.gy >= m_cachedBounds.gyMin && c.gy <= m_cachedBounds.gyMax;
	}
	/** Local cell of `c` in the cached tile (no divisions). */
	TLocalCell cachedLocal(const TGlobalCell& c) const { return {c.gx - m_cachedBounds.gxMin, c.gy - m_cachedBounds.gyMin}; }
	size_t updateRayInsideTile(CTile& tile, const TLocalCell& a, const TLocalCell& b, int crossedDelta,
							   int endDelta);

	TOptions m_options;
	CTiledGridGeometry m_geometry;
	float m_clampLogOdds;
	int m_clampCellUnits;  //!< m_clampLogOdds in cell units
	std::unordered_map<TTileIndex, std::unique_ptr<CTile>, TTileIndexHash> m_tiles;
	std::vector<TTileIndex> m_creationOrder;
	// Last tile touched: consecutive cells of a ray are almost always in it.
	TTileIndex m_cachedIndex;
	CTile* m_cachedTile = nullptr;
	TCellBounds m_cachedBounds;  //!< global cells of the cached tile
};

/** log(p / (1 - p)) */
float probabilityToLogOdds(double p);
/** 1 / (1 + exp(-l)) */
double logOddsToProbability(double logOdds);

}  // namespace hslam::maps
