/* hslam: laser points as an MRPT point map (ICP reference/current clouds and
 * k-d tree queries). The valid points of a scan come from
 * features::validScanPoints. */
#pragma once

#include <hslam/common/range_data.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace hslam::matching
{
mrpt::maps::CSimplePointsMap toPointsMap(const std::vector<mrpt::math::TPoint2D>& points);

/** The points of a scan without those seen at grazing incidence. A surface
 * seen at incidence a (from its normal) is sampled every r dtheta / cos(a)
 * along it: a point whose neighbouring beams' points (both that exist) lie
 * farther than r dtheta / cos(maxIncidence_rad) is a sparse sample of a
 * surface nearly along the beam (or a thin object seen by one beam). Point
 * matching pairs such a sample with whichever reference point is nearest,
 * not the same place: down a long corridor seen to 20 m, the side walls' far
 * points (every 2 m at 0.5 deg) pinned ICP along the axis it cannot
 * observe. Points with no valid neighbouring beam are kept (nothing tells).
 * maxIncidence_rad <= 0 keeps every point. */
std::vector<mrpt::math::TPoint2D> pointsOffGrazingIncidence(const common::TScanPoints& points,
															 double maxIncidence_rad);

/** Every k-th point, k = ceil(size / maxPoints), starting with the first:
 * at most maxPoints points, in scan order (0 keeps every point). A scanner
 * denser than the matchers need (1 081 beams at 0.25 deg) is matched like a
 * coarser one: the cost of ICP and of the point fallback of line matching
 * grows with the points, their accuracy much less. */
std::vector<mrpt::math::TPoint2D> everyKthPoint(std::vector<mrpt::math::TPoint2D> points, size_t maxPoints);

}  // namespace hslam::matching
