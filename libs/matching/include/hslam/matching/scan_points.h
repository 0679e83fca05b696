/* hslam: laser points as an MRPT point map (ICP reference/current clouds and
 * k-d tree queries). The valid points of a scan come from
 * features::validScanPoints. */
#pragma once

#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace hslam::matching
{
mrpt::maps::CSimplePointsMap toPointsMap(const std::vector<mrpt::math::TPoint2D>& points);

}  // namespace hslam::matching
