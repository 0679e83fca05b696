/* hslam: the local map of scan-to-map matching: the points and normals of a
 * set of keyframes in the world frame, with a nanoflann k-d tree (Debian
 * libnanoflann-dev) built once per set, not per query. Rebuilt only when the
 * set of keyframes or a keyframe pose changes (CKeyframeStore::revision). */
#pragma once

#include <hslam/matching/CKeyframeStore.h>

#include <Eigen/Core>
#include <nanoflann.hpp>

#include <memory>
#include <vector>

namespace hslam::matching
{
class CLocalPointMap
{
   public:
	CLocalPointMap();
	~CLocalPointMap();

	/** Rebuilds from the keyframes `ids` of `store` unless they (and the
	 * store's revision) are what the map already holds. */
	void update(const CKeyframeStore& store, const std::vector<size_t>& ids);
	bool empty() const { return m_points.empty(); }
	size_t size() const { return m_points.size(); }

	/** Index of the point nearest to `q` within max_distance_m, or -1. */
	long nearest(const Eigen::Vector2d& q, double max_distance_m) const;
	const Eigen::Vector2d& point(size_t i) const { return m_points[i]; }
	const Eigen::Vector2d& normal(size_t i) const { return m_normals[i]; }

	// nanoflann dataset adaptor interface
	size_t kdtree_get_point_count() const { return m_points.size(); }
	double kdtree_get_pt(size_t i, size_t dim) const { return m_points[i][static_cast<Eigen::Index>(dim)]; }
	template <class BBox>
	bool kdtree_get_bbox(BBox&) const
	{
		return false;
	}

   private:
	using TTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, CLocalPointMap>,
													  CLocalPointMap, 2, uint32_t>;
	std::vector<Eigen::Vector2d> m_points, m_normals;
	std::vector<size_t> m_ids;
	size_t m_revision = static_cast<size_t>(-1);
	std::unique_ptr<TTree> m_tree;
};

}  // namespace hslam::matching
