/* hslam: integer ray tracing between grid cells (Bresenham), shared by every
 * range-sensor model that clears cells along a ray. */
#pragma once

#include <hslam/maps/CTiledGridGeometry.h>

#include <cstdlib>

namespace hslam::maps
{
/** Calls visit(cell) for every cell on the digital segment from `from` to
 * `to`, both included, in order from `from`. */
template <class Visitor>
void forEachCellOnSegment(const TGlobalCell& from, const TGlobalCell& to, Visitor&& visit)
{
	const int dx = std::abs(to.gx - from.gx), dy = -std::abs(to.gy - from.gy);
	const int sx = from.gx < to.gx ? 1 : -1, sy = from.gy < to.gy ? 1 : -1;
	int err = dx + dy;
	TGlobalCell c = from;
	for (;;)
	{
		visit(c);
		if (c.gx == to.gx && c.gy == to.gy) break;
		const int e2 = 2 * err;
		if (e2 >= dy)
		{
			err += dy;
			c.gx += sx;
		}
		if (e2 <= dx)
		{
			err += dx;
			c.gy += sy;
		}
	}
}

}  // namespace hslam::maps
