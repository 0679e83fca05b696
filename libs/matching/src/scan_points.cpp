#include <hslam/matching/scan_points.h>

namespace hslam::matching
{
mrpt::maps::CSimplePointsMap toPointsMap(const std::vector<mrpt::math::TPoint2D>& points)
{
	mrpt::maps::CSimplePointsMap map;
	map.reserve(points.size());
	for (const auto& p : points) map.insertPointFast(static_cast<float>(p.x), static_cast<float>(p.y), 0);
	map.mark_as_modified();
	return map;
}

}  // namespace hslam::matching
