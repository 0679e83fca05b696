/* hslam: addressing of the tiled occupancy grid (thesis 4.6.1 i-ii).
 *
 * Cells are squares of `resolution_m` whose EDGES lie on integer multiples of
 * the resolution: global cell g covers [g res, (g + 1) res). Tiles hold N x N
 * cells; tile (0,0) is the home tile and the robot's start (the world origin)
 * is its exact centre: it covers [-N/2 res, N/2 res) = [-10 m, 10 m) for the
 * thesis' N = 200, res = 0.1 m.
 *
 * The thesis' formulas are written for a single 20 m tile (eq. 81-83) and its
 * tile version eq. 84 ("x_r = 200 T_x x 100 x_cell mm") is garbled. The
 * general form used here is
 *     g = floor(x / res)                            (eq. 81-82, any resolution)
 *     T = floor((g + N/2) / N),  l = g + N/2 - T N  (tile, local cell 0..N-1)
 *     x = (T N + l - N/2 + 1/2) res                 (eq. 83-84, cell centre)
 * with floor division, so negative coordinates resolve to the tile on their
 * side of the border (C++ '/' truncates towards zero and would not).
 * Deviation: eq. 81 (x_cell = 100 + ceil((x_mm - 50)/100)) centres local cell
 * (100,100) on the start pose; here that cell has its lower-left corner there.
 * The half-cell shift makes tile borders fall on round numbers (+-10 m) and
 * cell edges coincide with those of MRPT's COccupancyGridMap2D, which rounds
 * its limits to multiples of the resolution, so exported maps are
 * cell-for-cell identical to ours. */
#pragma once

#include <hslam/common/cell_key.h>
#include <mrpt/math/TPoint2D.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>

namespace hslam::maps
{
/** Integer tile coordinates relative to the home tile (0,0). */
struct TTileIndex
{
	int ix = 0, iy = 0;
	bool operator==(const TTileIndex& o) const { return ix == o.ix && iy == o.iy; }
	bool operator!=(const TTileIndex& o) const { return !(*this == o); }
};

struct TTileIndexHash
{
	size_t operator()(const TTileIndex& t) const { return common::cellKeyHash(t.ix, t.iy); }
};

/** Cell index in the whole (unbounded) grid; cell (0,0) spans [0, res) x [0, res). */
struct TGlobalCell
{
	int gx = 0, gy = 0;
	bool operator==(const TGlobalCell& o) const { return gx == o.gx && gy == o.gy; }
};

struct TGlobalCellHash
{
	size_t operator()(const TGlobalCell& c) const { return common::cellKeyHash(c.gx, c.gy); }
};

/** Cell index inside one tile, 0 .. N-1 on each axis. */
struct TLocalCell
{
	int lx = 0, ly = 0;
	bool operator==(const TLocalCell& o) const { return lx == o.lx && ly == o.ly; }
};

/** Inclusive range of global cells. */
struct TCellBounds
{
	int gxMin = 0, gxMax = -1, gyMin = 0, gyMax = -1;
	bool empty() const { return gxMax < gxMin || gyMax < gyMin; }
	int width() const { return empty() ? 0 : gxMax - gxMin + 1; }
	int height() const { return empty() ? 0 : gyMax - gyMin + 1; }
	/** Grows to the union with `o` (an empty box takes `o` as it is). */
	void include(const TCellBounds& o)
	{
		if (o.empty()) return;
		if (empty())
		{
			*this = o;
			return;
		}
		gxMin = std::min(gxMin, o.gxMin);
		gxMax = std::max(gxMax, o.gxMax);
		gyMin = std::min(gyMin, o.gyMin);
		gyMax = std::max(gyMax, o.gyMax);
	}
};

class CTiledGridGeometry
{
   public:
	CTiledGridGeometry(double resolution_m, int tileSizeCells);

	double resolution_m() const { return m_resolution_m; }
	int tileSizeCells() const { return m_tileSizeCells; }
	double tileSize_m() const { return m_resolution_m * m_tileSizeCells; }

	TGlobalCell cellOf(double x_m, double y_m) const
	{
		return {static_cast<int>(std::floor(x_m * m_inverseResolution)),
				static_cast<int>(std::floor(y_m * m_inverseResolution))};
	}
	mrpt::math::TPoint2D cellCentre(const TGlobalCell& c) const;

	TTileIndex tileOf(const TGlobalCell& c) const;
	TLocalCell localCellOf(const TGlobalCell& c) const;
	TGlobalCell globalCellOf(const TTileIndex& t, const TLocalCell& l) const;

	/** Global cells covered by one tile. */
	TCellBounds tileBounds(const TTileIndex& t) const;

   private:
	double m_resolution_m;
	double m_inverseResolution;
	int m_tileSizeCells;
	int m_half;  //!< N/2: local index of the cell centred on the tile centre
};

/** floor(a / b) for b > 0, correct for negative a. */
inline int floorDiv(int a, int b) { return (a >= 0) ? a / b : -((-a + b - 1) / b); }

}  // namespace hslam::maps
