/* hslam sim: CWorld ray casting (exact segment, circle and raster-cell hits). */
#include <hslam/sim/world.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::sim
{
using mrpt::math::TPoint2D;
using mrpt::math::TVector2D;

const char* objectKindName(EObjectKind kind)
{
	switch (kind)
	{
		case EObjectKind::none: return "none";
		case EObjectKind::wall: return "wall";
		case EObjectKind::furniture: return "furniture";
		case EObjectKind::person_leg: return "person_leg";
		case EObjectKind::map_cell: return "map_cell";
	}
	return "none";
}

namespace
{
double cross(const TVector2D& a, const TVector2D& b) { return a.x * b.y - a.y * b.x; }
double dot(const TVector2D& a, const TVector2D& b) { return a.x * b.x + a.y * b.y; }

/** Keeps `candidate` if it is nearer than `best`. */
void keepNearest(TRayHit& best, double t, const TVector2D& normal, const TObjectTag& tag)
{
	if (t >= best.range_m) return;
	best.hit = true;
	best.range_m = t;
	best.normal = normal;
	best.tag = tag;
}

void intersectSegment(const TPoint2D& o, const TVector2D& d, const TSegment& s, TRayHit& best)
{
	const TVector2D e{s.b.x - s.a.x, s.b.y - s.a.y};
	const double denom = cross(d, e);
	if (std::abs(denom) < 1e-12) return;  // parallel: a zero-thickness wall seen edge-on is not hit
	const TVector2D ao{s.a.x - o.x, s.a.y - o.y};
	const double t = cross(ao, e) / denom;
	const double u = cross(ao, d) / denom;
	if (t <= 1e-9 || u < 0.0 || u > 1.0) return;
	const double len = std::hypot(e.x, e.y);
	TVector2D n{-e.y / len, e.x / len};
	if (dot(n, d) > 0) n = TVector2D{-n.x, -n.y};
	keepNearest(best, t, n, s.tag);
}

void intersectCircle(const TPoint2D& o, const TVector2D& d, const TCircle& c, TRayHit& best)
{
	const TVector2D f{o.x - c.centre.x, o.y - c.centre.y};
	const double cc = dot(f, f) - c.radius_m * c.radius_m;
	if (cc <= 0) return;  // origin inside the circle
	const double b = dot(f, d);
	const double disc = b * b - cc;
	if (disc < 0 || b > 0) return;  // misses, or circle behind the origin
	const double t = -b - std::sqrt(disc);
	if (t <= 1e-9 || t >= best.range_m) return;
	const TVector2D n{(o.x + t * d.x - c.centre.x) / c.radius_m, (o.y + t * d.y - c.centre.y) / c.radius_m};
	keepNearest(best, t, n, c.tag);
}

/** Amanatides-Woo walk through the raster; exact entry distance and face normal. */
void intersectRaster(const TPoint2D& o, const TVector2D& d, const TOccupancyRaster& r, TRayHit& best)
{
	if (r.empty()) return;
	const double res = r.resolution_m;
	const double gx = (o.x - r.x0_m) / res, gy = (o.y - r.y0_m) / res;  // origin in cell units
	int i = static_cast<int>(std::floor(gx)), j = static_cast<int>(std::floor(gy));
	const TObjectTag tag{EObjectKind::map_cell, -1, 0};
	if (r.isOccupiedCell(i, j))
	{
		keepNearest(best, 0.0, TVector2D{-d.x, -d.y}, tag);
		return;
	}
	const double inf = std::numeric_limits<double>::infinity();
	const int stepI = d.x > 0 ? 1 : -1, stepJ = d.y > 0 ? 1 : -1;
	const double tDeltaX = d.x != 0 ? res / std::abs(d.x) : inf;
	const double tDeltaY = d.y != 0 ? res / std::abs(d.y) : inf;
	double tMaxX = d.x != 0 ? ((d.x > 0 ? (i + 1 - gx) : (gx - i)) * res) / std::abs(d.x) : inf;
	double tMaxY = d.y != 0 ? ((d.y > 0 ? (j + 1 - gy) : (gy - j)) * res) / std::abs(d.y) : inf;
	const double tLimit = best.range_m;
	// Cells outside the raster are free: stop once the ray has left it for good.
	for (;;)
	{
		double t;
		TVector2D n;
		if (tMaxX < tMaxY)
		{
			t = tMaxX;
			i += stepI;
			tMaxX += tDeltaX;
			n = TVector2D{-static_cast<double>(stepI), 0};
		}
		else
		{
			t = tMaxY;
			j += stepJ;
			tMaxY += tDeltaY;
			n = TVector2D{0, -static_cast<double>(stepJ)};
		}
		if (t >= tLimit) return;
		if ((stepI > 0 && i >= r.width) || (stepI < 0 && i < 0) || (stepJ > 0 && j >= r.height) ||
			(stepJ < 0 && j < 0))
			return;
		if (r.isOccupiedCell(i, j))
		{
			keepNearest(best, t, n, tag);
			return;
		}
	}
}
}  // namespace

TRayHit CWorld::castRay(const TPoint2D& origin, double angle_rad, double maxRange_m, bool includeDynamic) const
{
	const TVector2D d{std::cos(angle_rad), std::sin(angle_rad)};
	TRayHit best;
	best.range_m = maxRange_m;
	for (const auto& s : m_segments) intersectSegment(origin, d, s, best);
	for (const auto& c : m_circles) intersectCircle(origin, d, c, best);
	if (includeDynamic)
		for (const auto& c : m_dynamic) intersectCircle(origin, d, c, best);
	intersectRaster(origin, d, m_raster, best);
	if (best.hit)
	{
		best.point = TPoint2D{origin.x + best.range_m * d.x, origin.y + best.range_m * d.y};
		best.incidence_rad = std::acos(std::clamp(-dot(d, best.normal), -1.0, 1.0));
	}
	else
		best.range_m = maxRange_m;
	return best;
}

bool CWorld::collides(const TPoint2D& p, double clearance_m) const
{
	for (const auto& c : m_circles)
		if (std::hypot(p.x - c.centre.x, p.y - c.centre.y) < c.radius_m + clearance_m) return true;
	for (const auto& s : m_segments)
	{
		const TVector2D e{s.b.x - s.a.x, s.b.y - s.a.y};
		const double len2 = dot(e, e);
		const double u = len2 > 0 ? std::clamp(dot(TVector2D{p.x - s.a.x, p.y - s.a.y}, e) / len2, 0.0, 1.0) : 0.0;
		if (std::hypot(p.x - (s.a.x + u * e.x), p.y - (s.a.y + u * e.y)) < clearance_m) return true;
	}
	if (!m_raster.empty())
	{
		const double res = m_raster.resolution_m;
		const int r = static_cast<int>(std::ceil(clearance_m / res));
		const int ci = static_cast<int>(std::floor((p.x - m_raster.x0_m) / res));
		const int cj = static_cast<int>(std::floor((p.y - m_raster.y0_m) / res));
		for (int j = cj - r; j <= cj + r; ++j)
			for (int i = ci - r; i <= ci + r; ++i)
				if (m_raster.isOccupiedCell(i, j))
				{
					const double cx = std::clamp(p.x, m_raster.x0_m + i * res, m_raster.x0_m + (i + 1) * res);
					const double cy = std::clamp(p.y, m_raster.y0_m + j * res, m_raster.y0_m + (j + 1) * res);
					if (std::hypot(p.x - cx, p.y - cy) <= clearance_m) return true;
				}
	}
	return false;
}

TWorldBounds CWorld::bounds() const
{
	double inf = std::numeric_limits<double>::infinity();
	TWorldBounds b{inf, inf, -inf, -inf};
	auto add = [&](double x, double y) {
		b.min_x = std::min(b.min_x, x);
		b.min_y = std::min(b.min_y, y);
		b.max_x = std::max(b.max_x, x);
		b.max_y = std::max(b.max_y, y);
	};
	for (const auto& s : m_segments)
	{
		add(s.a.x, s.a.y);
		add(s.b.x, s.b.y);
	}
	for (const auto& c : m_circles)
	{
		add(c.centre.x - c.radius_m, c.centre.y - c.radius_m);
		add(c.centre.x + c.radius_m, c.centre.y + c.radius_m);
	}
	if (!m_raster.empty())
	{
		add(m_raster.x0_m, m_raster.y0_m);
		add(m_raster.x0_m + m_raster.width * m_raster.resolution_m, m_raster.y0_m + m_raster.height * m_raster.resolution_m);
	}
	if (b.min_x > b.max_x) return TWorldBounds{};
	return b;
}

}  // namespace hslam::sim
