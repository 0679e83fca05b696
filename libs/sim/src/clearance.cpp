/* hslam sim: clearance (see clearance.h). */
#include <hslam/sim/clearance.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::sim
{
namespace
{
double segmentDistance(const TSegment& s, const mrpt::math::TPoint2D& p)
{
	const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
	const double len2 = dx * dx + dy * dy;
	const double t = len2 > 0 ? std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2, 0.0, 1.0) : 0.0;
	return std::hypot(p.x - (s.a.x + t * dx), p.y - (s.a.y + t * dy));
}
}  // namespace

double clearance_m(const CWorld& world, const mrpt::math::TPoint2D& p, bool includePeople)
{
	double best = std::numeric_limits<double>::infinity();
	for (const auto& s : world.segments()) best = std::min(best, segmentDistance(s, p));
	auto nearestCircle = [&](const std::vector<TCircle>& circles) {
		for (const auto& c : circles) best = std::min(best, std::hypot(p.x - c.centre.x, p.y - c.centre.y) - c.radius_m);
	};
	nearestCircle(world.circles());
	if (includePeople) nearestCircle(world.dynamicCircles());
	const auto& r = world.raster();
	if (!r.empty())
		for (int j = 0; j < r.height; ++j)
			for (int i = 0; i < r.width; ++i)
				if (r.isOccupiedCell(i, j))
					best = std::min(best, std::hypot(p.x - (r.x0_m + (i + 0.5) * r.resolution_m),
													 p.y - (r.y0_m + (j + 0.5) * r.resolution_m)) -
											  0.5 * r.resolution_m);
	return best;
}
}  // namespace hslam::sim
