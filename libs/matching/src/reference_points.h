/* hslam matching (private): one view of an ICP reference for the functions
 * that read it after the match (icp_covariance.cpp, alignment_fit.cpp),
 * whether it is MRPT's point map with its k-d tree or a CPointIndex2D. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace hslam::matching::detail
{
/** Reference points seen through MRPT's map and k-d tree... */
struct TMrptReference
{
	const mrpt::maps::CSimplePointsMap& map;
	void nearest(float x, float y, size_t k, std::vector<size_t>& idx, std::vector<float>& d2) const
	{
		map.kdTreeNClosestPoint2DIdx(x, y, k, idx, d2);
	}
	/** Squared distance to the nearest reference point. */
	float nearestDistance2(float x, float y) const
	{
		float d2 = 0;
		map.kdTreeClosestPoint2D(x, y, d2);
		return d2;
	}
	Eigen::Vector2d point(size_t i) const { return {map.getPointsBufferRef_x()[i], map.getPointsBufferRef_y()[i]}; }
};

/** ...or through a CPointIndex2D. */
struct TIndexReference
{
	const CPointIndex2D& index;
	void nearest(float x, float y, size_t k, std::vector<size_t>& idx, std::vector<float>& d2) const
	{
		uint32_t found[32];
		d2.resize(std::min<size_t>(k, 32));
		const size_t n = index.nearest(x, y, d2.size(), found, d2.data());
		idx.assign(found, found + n);
		d2.resize(n);
	}
	float nearestDistance2(float x, float y) const
	{
		uint32_t i = 0;
		float d2 = 0;
		return index.nearest(x, y, 1, &i, &d2) ? d2 : 1e30f;
	}
	Eigen::Vector2d point(size_t i) const { return {index.x(i), index.y(i)}; }
};
}  // namespace hslam::matching::detail
