/* The free-space check of a loop closure (see free_space_check.h). */
#include <hslam/graph/free_space_check.h>
#include <hslam/maps/grid_ray_tracing.h>

#include <cmath>

namespace hslam::graph
{
namespace
{
constexpr uint8_t kWallValue = 190;  //!< a cell holding a reference point (exp(-0.5 x 0.7^2) x 255 = 199)
constexpr int kEndCells = 2;  //!< cells before a beam's end point that are not its free space
constexpr int kFreeSideCells[] = {2, 3, 4};  //!< where the free side of a wall hit is looked for

/** A beam from (x0, y0) to (x1, y1) in the grid's frame, walked in half-cell steps. */
struct TBeam
{
	double x0, y0, dx = 0, dy = 0;  //!< start and one step
	int steps = 0;  //!< steps to the end point
	TBeam(double ax, double ay, double bx, double by, double step) : x0(ax), y0(ay)
	{
		const double length = std::hypot(bx - ax, by - ay);
		steps = static_cast<int>(length / step);
		if (length > 0) dx = (bx - ax) / length * step, dy = (by - ay) / length * step;
	}
	double x(int i) const { return x0 + i * dx; }
	double y(int i) const { return y0 + i * dy; }
};

bool approachedFromFreeSide(const CMultiResolutionGrid& grid, const CObservedFreeSpace& free, const TBeam& beam)
{
	for (const int cells : kFreeSideCells)
	{
		const int i = beam.steps - 2 * cells;
		if (i >= 0 && free.isFree(grid.cellX(beam.x(i)), grid.cellY(beam.y(i)))) return true;
	}
	return false;
}
}  // namespace

void CObservedFreeSpace::build(const CMultiResolutionGrid& grid, const std::vector<TSubmapView>& views)
{
	m_width = grid.width(), m_height = grid.height();
	m_free.assign(static_cast<size_t>(m_width) * m_height, 0);
	const double endGap_m = kEndCells * grid.resolution_m();
	auto mark = [&](const maps::TGlobalCell& c) {
		if (c.gx >= 0 && c.gy >= 0 && c.gx < m_width && c.gy < m_height)
			m_free[static_cast<size_t>(c.gy) * m_width + c.gx] = 1;
	};
	for (const auto& view : views)
	{
		const maps::TGlobalCell from{grid.cellX(view.origin.x), grid.cellY(view.origin.y)};
		for (const auto& p : view.points)
		{
			const double dx = p.x - view.origin.x, dy = p.y - view.origin.y, range = std::hypot(dx, dy);
			if (range <= endGap_m) continue;
			const double k = (range - endGap_m) / range;  // stop kEndCells before the point
			const maps::TGlobalCell to{grid.cellX(view.origin.x + k * dx), grid.cellY(view.origin.y + k * dy)};
			maps::forEachCellOnSegment(from, to, mark);
		}
	}
}

TFreeSideFigures freeSideFigures(const CMultiResolutionGrid& grid, const CObservedFreeSpace& free,
								 const std::vector<mrpt::math::TPoint2Df>& query, const mrpt::math::TPose2D& pose)
{
	TFreeSideFigures f;
	if (grid.empty()) return f;
	const double c = std::cos(pose.phi), s = std::sin(pose.phi), step = 0.5 * grid.resolution_m();
	for (const auto& p : query)
	{
		const TBeam beam(pose.x, pose.y, pose.x + c * p.x - s * p.y, pose.y + s * p.x + c * p.y, step);
		if (grid.value(0, grid.cellX(beam.x(beam.steps)), grid.cellY(beam.y(beam.steps))) < kWallValue) continue;
		++f.wall_hits;
		if (approachedFromFreeSide(grid, free, beam)) ++f.from_free_side;
	}
	return f;
}
}  // namespace hslam::graph
