/* hslam graph: the reference of the correlative scan matcher.
 *
 * A likelihood field rasterised once from reference points (a submap: several
 * keyframes' points in one frame): cell value = exp(-d^2 / 2 sigma^2) for the
 * distance d to the nearest reference point (within 3 sigma), stored as
 * 0..255. Above it, levels h = 1..L-1 hold, per cell, the maximum over the
 * 2^h x 2^h block of finest cells starting at that cell (Olson 2009,
 * "Real-time correlative scan matching", section IV; Cartographer's
 * PrecomputationGrid2D). A query scored on level h is therefore an upper
 * bound of its score at every translation of that block: the bound
 * branch-and-bound needs. The grid carries a margin of 2^(L-1) cells so a
 * block never reaches past stored cells that could hold a point. */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace hslam::graph
{
class CMultiResolutionGrid
{
   public:
	/** Builds the field and `levels` max-pooled levels (1 = finest only),
	 * replacing what the grid held (its buffers are reused). */
	void build(const std::vector<mrpt::math::TPoint2Df>& points, double resolution_m, double kernelSigma_m, int levels);

	bool empty() const { return m_levels.empty(); }
	int levelCount() const { return static_cast<int>(m_levels.size()); }
	double resolution_m() const { return m_res; }
	double originX_m() const { return m_x0; }  //!< x of the low edge of cell 0
	double originY_m() const { return m_y0; }
	/** Cell index of a coordinate (floor), in the grid's own integer frame. */
	int cellX(double x_m) const { return static_cast<int>(std::floor((x_m - m_x0) / m_res)); }
	int cellY(double y_m) const { return static_cast<int>(std::floor((y_m - m_y0) / m_res)); }
	/** Value of cell (ix, iy) at `level` in 0..255 (0 outside the grid). */
	uint8_t value(int level, int ix, int iy) const
	{
		if (ix < 0 || iy < 0 || ix >= m_width || iy >= m_height) return 0;
		return m_levels[static_cast<size_t>(level)][static_cast<size_t>(iy) * m_width + ix];
	}
	/** Row-major cells of `level` (width() x height()), no bounds: for
	 * callers that have checked their indices once for many reads. */
	const uint8_t* levelData(int level) const { return m_levels[static_cast<size_t>(level)].data(); }
	int width() const { return m_width; }
	int height() const { return m_height; }
	/** Bytes held by all levels. */
	size_t memoryBytes() const { return m_levels.size() * static_cast<size_t>(m_width) * m_height; }

   private:
	void stampPoints(const std::vector<mrpt::math::TPoint2Df>& points, double kernelSigma_m);
	/** Fills level `level` (already allocated) by pooling level - 1. */
	void poolLevel(int level);

	double m_res = 0.05, m_x0 = 0, m_y0 = 0;
	int m_width = 0, m_height = 0;
	std::vector<std::vector<uint8_t>> m_levels;
	std::vector<uint8_t> m_rows;  //!< scratch of poolLevel(), kept for the next build
};

}  // namespace hslam::graph
