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
	/** Squared distance to the nearest reference point (exact; the bound is
	 * TIndexReference's). */
	float nearestDistance2(float x, float y, float /*max_m*/) const
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
	/** Squared distance to the nearest reference point when it is below
	 * max_m, else some value >= max_m^2 (the search stops there). */
	float nearestDistance2(float x, float y, float max_m) const
	{
		uint32_t i = 0;
		float d2 = 0, exact_m = 0;  // found beyond exact_m (>= max_m): d2 >= max_m^2 as promised
		return index.nearestWithin(x, y, 1, max_m, &i, &d2, exact_m) ? d2 : 1e30f;
	}
	Eigen::Vector2d point(size_t i) const { return {index.x(i), index.y(i)}; }
};
/** The point of the reference surface nearest to q: on the segment from
 * q's nearest reference point to one of the next two nearest, if they are at
 * most maxSegment_m apart (neighbouring samples of one wall), else the
 * nearest point itself. Unlike the nearest point it does not alias on
 * sampled walls (alignment_fit.h). False without reference points; idx and
 * d2 are scratch. */
template <class Reference>
bool nearestSurfacePoint(const Reference& reference, const Eigen::Vector2d& q, double maxSegment_m,
						 Eigen::Vector2d& foot, std::vector<size_t>& idx, std::vector<float>& d2)
{
	reference.nearest(static_cast<float>(q.x()), static_cast<float>(q.y()), 3, idx, d2);
	if (idx.empty()) return false;
	const Eigen::Vector2d a = reference.point(idx[0]);
	foot = a;
	double best = (a - q).squaredNorm();
	for (size_t j = 1; j < idx.size(); ++j)
	{
		const Eigen::Vector2d ab = reference.point(idx[j]) - a;
		const double length2 = ab.squaredNorm();
		if (length2 <= 0 || length2 > maxSegment_m * maxSegment_m) continue;
		const Eigen::Vector2d f = a + std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) * ab;
		if ((f - q).squaredNorm() < best) best = (f - q).squaredNorm(), foot = f;
	}
	return true;
}
}  // namespace hslam::matching::detail
