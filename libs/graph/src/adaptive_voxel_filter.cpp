#include <hslam/common/cell_key.h>
#include <hslam/graph/adaptive_voxel_filter.h>

#include <cmath>
#include <unordered_set>

namespace hslam::graph
{
std::vector<mrpt::math::TPoint2Df> voxelFilter(const std::vector<mrpt::math::TPoint2Df>& points, double cell_m)
{
	std::vector<mrpt::math::TPoint2Df> out;
	std::unordered_set<int64_t> used;
	used.reserve(points.size());
	for (const auto& p : points)
	{
		const auto key = common::cellKey(static_cast<int>(std::floor(p.x / cell_m)), static_cast<int>(std::floor(p.y / cell_m)));
		if (used.insert(key).second) out.push_back(p);
	}
	return out;
}

std::vector<mrpt::math::TPoint2Df> adaptiveVoxelFilter(const std::vector<mrpt::math::TPoint2Df>& points,
														size_t minPoints, double maxCell_m)
{
	if (minPoints == 0 || points.size() <= minPoints || maxCell_m <= 0) return points;
	auto coarsest = voxelFilter(points, maxCell_m);
	if (coarsest.size() >= minPoints) return coarsest;
	// halve the cell until enough points remain, then bisect between the
	// last cell that kept too few (high) and the first that kept enough (low)
	double high = maxCell_m;
	for (double low = 0.5 * maxCell_m; low > 1e-3 * maxCell_m; high = low, low *= 0.5)
	{
		auto kept = voxelFilter(points, low);
		if (kept.size() < minPoints) continue;
		while (high / low > 1.1)
		{
			const double mid = 0.5 * (low + high);
			auto candidate = voxelFilter(points, mid);
			if (candidate.size() >= minPoints)
				low = mid, kept = std::move(candidate);
			else
				high = mid;
		}
		return kept;
	}
	return points;
}
}  // namespace hslam::graph
