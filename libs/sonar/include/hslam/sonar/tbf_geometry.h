/* hslam: circle-circle intersection for triangulation-based fusion (TBF) of
 * sonar readings (thesis 4.3.2, eq. 37-49).
 *
 * Two sonar readings taken from positions s1, s2 with ranges r1, r2 are two
 * circular arcs; an edge or corner that produced both echoes lies on their
 * intersection. With d = s1 - s2 (eq. 45-46), ds = |d| (eq. 47) and
 *     k = (ds^2 + r1^2 - r2^2) / (2 ds)                          (eq. 49)
 * (the distance from s1 to the chord midpoint, towards s2), the two points are
 *     T = s1 - (k / ds) d  -+  (h / ds) (-d_y, d_x),   h = sqrt(r1^2 - k^2)
 * which is eq. 43-44 of the thesis. Real intersections exist iff
 * |r1 - r2| <= ds <= r1 + r2 (k^2 <= r1^2).
 *
 * wijkEq37Candidates() evaluates eq. 37-38 of Wijk & Christensen (2000) as
 * the thesis quotes them; the thesis (4.3.3) found they do not give the
 * intersection, and tests/sonar proves it on exact geometry: the points they
 * produce do not lie on both circles (they only coincide for special cases). */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <array>
#include <optional>

namespace hslam::sonar
{
/** Both intersection points of circle (c1, r1) and circle (c2, r2), or
 * nullopt if the circles do not meet or share their centre (eq. 43-49). A
 * tangent pair returns the same point twice. */
std::optional<std::array<mrpt::math::TPoint2D, 2>> circleCircleIntersection(const mrpt::math::TPoint2D& c1, double r1,
																		   const mrpt::math::TPoint2D& c2, double r2);

/** Eq. 37-38 (Wijk & Christensen, as quoted by the thesis), both sign
 * choices; nullopt if the square root is of a negative number. Kept only to
 * show it is wrong (see the file comment); do not use for triangulation. */
std::optional<std::array<mrpt::math::TPoint2D, 2>> wijkEq37Candidates(const mrpt::math::TPoint2D& s1, double r1,
																	 const mrpt::math::TPoint2D& s2, double r2);

}  // namespace hslam::sonar
