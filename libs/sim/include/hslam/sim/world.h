/* hslam sim: the simulated world and exact 2D ray casting.
 *
 * The world is a set of primitives with exact geometry:
 *  - segments (walls; zero thickness, both sides reflect),
 *  - circles (furniture legs, pillars, and the legs of walking people, which are
 *    replaced every simulation step through setDynamicCircles()),
 *  - optionally an occupancy raster (a world loaded from a PNG or an MRPT
 *    .gridmap): every occupied cell is an axis-aligned square, traversed with
 *    the Amanatides-Woo grid walk so hits and face normals are exact.
 *
 * castRay() returns the first hit along a ray: range, hit point, the unit
 * surface normal facing the ray, the incidence angle (between the reversed ray
 * and the normal; 0 = perpendicular hit; what the specular sonar model of
 * thesis 4.3.5-4.3.6 needs) and the tag of the object hit (kind, group id =
 * wall/furniture/person id, part = leg index), which the per-beam ground truth
 * labels of the legs issue (thesis 4.7) are made from.
 *
 * No file I/O here (see world_loading.h). */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <vector>

namespace hslam::sim
{
enum class EObjectKind : uint8_t
{
	none = 0,  //!< nothing hit
	wall = 1,  //!< a wall segment
	furniture = 2,  //!< a furniture leg, pillar or other static circle
	person_leg = 3,  //!< a leg of a walking person
	map_cell = 4  //!< an occupied cell of a raster world
};

/** Name used in CSV files: "none", "wall", "furniture", "person_leg", "map_cell". */
const char* objectKindName(EObjectKind kind);

/** Which object a primitive belongs to. */
struct TObjectTag
{
	EObjectKind kind = EObjectKind::wall;
	int group = -1;  //!< wall chain id, furniture id or person id (-1 = none)
	int part = 0;  //!< leg index within a person or a piece of furniture
};

struct TSegment
{
	mrpt::math::TPoint2D a, b;  //!< end points, m
	TObjectTag tag;
};

struct TCircle
{
	mrpt::math::TPoint2D centre;  //!< m
	double radius_m = 0.05;
	TObjectTag tag{EObjectKind::furniture, -1, 0};
};

/** Occupancy raster: cell (i, j) covers [x0 + i*res, x0 + (i+1)*res) x [y0 + j*res, ...). */
struct TOccupancyRaster
{
	double x0_m = 0, y0_m = 0, resolution_m = 0.05;
	int width = 0, height = 0;
	std::vector<uint8_t> occupied;  //!< width*height, row-major by j (y), 1 = occupied

	bool empty() const { return width <= 0 || height <= 0; }
	bool isOccupiedCell(int i, int j) const
	{
		return i >= 0 && j >= 0 && i < width && j < height && occupied[static_cast<size_t>(j) * width + i] != 0;
	}
};

struct TRayHit
{
	bool hit = false;
	double range_m = 0;  //!< distance from the origin to the hit point (maxRange if no hit)
	mrpt::math::TPoint2D point;  //!< hit point, m
	mrpt::math::TVector2D normal;  //!< unit surface normal at the hit, facing the ray origin
	double incidence_rad = 0;  //!< angle between the reversed ray and the normal, [0, pi/2]
	TObjectTag tag{EObjectKind::none, -1, 0};
};

struct TWorldBounds
{
	double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
	bool empty() const { return max_x <= min_x || max_y <= min_y; }
};

class CWorld
{
   public:
	void addSegment(const TSegment& segment) { m_segments.push_back(segment); }
	void addCircle(const TCircle& circle) { m_circles.push_back(circle); }
	void setRaster(TOccupancyRaster raster) { m_raster = std::move(raster); }
	/** Replaces the moving circles (the legs of people at the current time). */
	void setDynamicCircles(std::vector<TCircle> circles) { m_dynamic = std::move(circles); }

	const std::vector<TSegment>& segments() const { return m_segments; }
	const std::vector<TCircle>& circles() const { return m_circles; }
	const std::vector<TCircle>& dynamicCircles() const { return m_dynamic; }
	const TOccupancyRaster& raster() const { return m_raster; }

	/** First hit of the ray from `origin` in direction `angle_rad` within
	 * (0, maxRange_m]. A circle that contains the origin is ignored (a sensor
	 * inside a leg sees out of it). */
	TRayHit castRay(const mrpt::math::TPoint2D& origin, double angle_rad, double maxRange_m,
					bool includeDynamic = true) const;

	/** True if the point lies inside a circle, an occupied raster cell or
	 * within `clearance_m` of a segment (static objects only). */
	bool collides(const mrpt::math::TPoint2D& p, double clearance_m) const;

	/** Bounding box of all static geometry (empty if there is none). */
	TWorldBounds bounds() const;

   private:
	std::vector<TSegment> m_segments;
	std::vector<TCircle> m_circles;
	std::vector<TCircle> m_dynamic;
	TOccupancyRaster m_raster;
};

}  // namespace hslam::sim
