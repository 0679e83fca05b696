/* hslam sim: a scene = the static world + the walking people + the true
 * corners of the walls, parsed from a small text format, and the explicit
 * loaders of raster worlds (PNG image with a scale, MRPT .gridmap[.gz]).
 *
 * Text format (one item per line, '#' starts a comment, lengths in m, angles in deg):
 *   wall x0 y0 x1 y1                   thin wall, both sides free (its ends are "end" corners)
 *   polyline x0 y0 x1 y1 ... xn yn      connected walls; free space on the LEFT of the walking direction
 *   room x0 y0 ... xn yn                closed polygon, free inside (any orientation)
 *   box cx cy width height [yaw]        closed rectangular obstacle (cupboard, desk block), free outside
 *   circle x y r                        pillar / single leg
 *   chair x y [yaw] [size=0.45] [leg_r=0.015]          four thin legs on a square (thesis fig. 155 confusers)
 *   table x y width depth [yaw] [leg_r=0.025]           four legs at the corners
 *   person speed_mps leg_r step_m x0 y0 x1 y1 ... [loop|pingpong] [delay=S]
 *
 * Corners: where two consecutive walls of a polyline/room/box meet at more
 * than 10 deg; "concave" = seen from free space as an inside corner (a sonar
 * corner reflector, thesis 4.3 TBF), "convex" = an outside edge; "end" = free end of a wall or
 * polyline. Walls that only touch (not in one chain) do not make a corner:
 * draw connected walls as one polyline/room. */
#pragma once

#include <hslam/sim/CWalkingPerson.h>
#include <hslam/sim/world.h>

#include <string>
#include <vector>

namespace hslam::sim
{
enum class ECornerKind
{
	concave,
	convex,
	end
};
const char* cornerKindName(ECornerKind kind);

struct TWorldCorner
{
	int id = 0;
	mrpt::math::TPoint2D point;
	ECornerKind kind = ECornerKind::concave;
	double free_angle_deg = 90;  //!< opening angle of the corner on the free side (deg)
	int chain = -1;  //!< wall chain (group) id
};

struct TScene
{
	CWorld world;
	std::vector<TPersonSpec> people;
	std::vector<TWorldCorner> corners;
};

/** Parses the text format; `name` (file name) and the line number are in
 * every error (std::runtime_error). */
TScene parseSceneText(const std::string& text, const std::string& name);

/** Reads and parses a scene file. */
TScene loadSceneFile(const std::string& path);

/** Raster world from an image (dark pixels, gray < threshold*255, are
 * occupied); pixel (0,0) is the top-left, i.e. the image is north-up, its
 * bottom-left corner at (x0_m, y0_m). */
TOccupancyRaster loadOccupancyImage(const std::string& path, double resolution_m, double x0_m, double y0_m,
									double occupiedBelow = 0.5);

/** Raster world from an MRPT COccupancyGridMap2D file (.gridmap, optionally
 * gz-compressed, as written by hslam-process or observations2map): cells with
 * p(free) < 1 - occupiedAbove are occupied. */
TOccupancyRaster loadGridMapFile(const std::string& path, double occupiedAbove = 0.5);

}  // namespace hslam::sim
