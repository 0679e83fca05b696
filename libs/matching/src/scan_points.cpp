#include <hslam/matching/scan_points.h>

#include <cmath>

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

std::vector<mrpt::math::TPoint2D> pointsOffGrazingIncidence(const common::TScanPoints& points,
															 double maxIncidence_rad)
{
	if (maxIncidence_rad <= 0) return points.xy;
	const double stretch = 1.0 / std::cos(maxIncidence_rad);
	std::vector<mrpt::math::TPoint2D> out;
	out.reserve(points.size());
	const size_t n = points.size();
	for (size_t i = 0; i < n; ++i)
	{
		const double limit = stretch * points.range_m[i] * points.beam_step_rad;
		bool anyNeighbour = false, nearNeighbour = false;
		for (const size_t j : {i - 1, i + 1})  // i - 1 wraps to SIZE_MAX for i = 0
		{
			if (j >= n || (points.beam[j] + 1 != points.beam[i] && points.beam[i] + 1 != points.beam[j])) continue;
			anyNeighbour = true;
			nearNeighbour |= std::hypot(points.xy[j].x - points.xy[i].x, points.xy[j].y - points.xy[i].y) <= limit;
		}
		if (nearNeighbour || !anyNeighbour) out.push_back(points.xy[i]);
	}
	return out;
}

std::vector<mrpt::math::TPoint2D> everyKthPoint(std::vector<mrpt::math::TPoint2D> points, size_t maxPoints)
{
	if (maxPoints == 0 || points.size() <= maxPoints) return points;
	const size_t k = (points.size() + maxPoints - 1) / maxPoints;
	size_t kept = 0;
	for (size_t i = 0; i < points.size(); i += k) points[kept++] = points[i];
	points.resize(kept);
	return points;
}

}  // namespace hslam::matching
