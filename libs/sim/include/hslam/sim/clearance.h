/* hslam sim: distance from a point to the nearest obstacle surface of a world
 * (static segments and circles, and the legs of people at the current time).
 * Used to score navigation runs (minimum clearance, collisions); raster
 * worlds are scored by their occupied cells' centres. */
#pragma once

#include <hslam/sim/world.h>

namespace hslam::sim
{
/** Nearest obstacle surface from p (m); infinity in an empty world.
 * includePeople = false: static geometry only. */
double clearance_m(const CWorld& world, const mrpt::math::TPoint2D& p, bool includePeople = true);
}  // namespace hslam::sim
