/* hslam: a 2D point cloud with nanoflann k-d trees (Debian libnanoflann-dev)
 * over flat float arrays: the reference of CPointToPointIcp and of the
 * geometric ICP covariance.
 *
 * A scan-to-map reference changes a little at every keyframe (one keyframe
 * in, the oldest out), and rebuilding one tree over all its points each time
 * was most of the matcher's cost. The points are therefore kept in two parts:
 * a bulk part whose tree is built rarely, and a small recent part (the
 * keyframes added since) whose tree is rebuilt when it grows. Points at the
 * front of the bulk part can be retired (a keyframe leaving the window)
 * without rebuilding: queries skip them. A query returns the exact k nearest
 * live points of both parts. Indices address the bulk part first, then the
 * recent part. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <nanoflann.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace hslam::matching
{
class CPointIndex2D
{
   public:
	CPointIndex2D();
	~CPointIndex2D();
	CPointIndex2D(CPointIndex2D&&) noexcept;
	CPointIndex2D& operator=(CPointIndex2D&&) noexcept;

	/** Replaces all points (into the bulk part) and rebuilds. */
	void build(std::vector<float> xs, std::vector<float> ys);
	/** Adds points to the recent part (its tree is rebuilt). */
	void append(const std::vector<float>& xs, const std::vector<float>& ys);
	/** Bulk points with an index below `firstLive` are skipped from now on. */
	void retireBelow(size_t firstLive) { m_firstLive = firstLive; }

	bool empty() const { return liveSize() == 0; }
	/** Addressable points (bulk, retired ones included, then recent). */
	size_t size() const { return m_bulk->x.size() + m_recent->x.size(); }
	size_t liveSize() const { return size() - m_firstLive; }
	size_t bulkSize() const { return m_bulk->x.size(); }
	size_t recentSize() const { return m_recent->x.size(); }
	float x(size_t i) const { return i < bulkSize() ? m_bulk->x[i] : m_recent->x[i - bulkSize()]; }
	float y(size_t i) const { return i < bulkSize() ? m_bulk->y[i] : m_recent->y[i - bulkSize()]; }

	/** Up to k (<= 32) nearest live points of (x, y): indices and squared
	 * distances, nearest first. Returns how many were found. */
	size_t nearest(float x, float y, size_t k, uint32_t* indices, float* distances2) const;

	/** The points, as nanoflann's dataset adaptor (kept on the heap: the
	 * trees refer to them, so the index can be moved). */
	struct TCloud
	{
		std::vector<float> x, y;
		size_t kdtree_get_point_count() const { return x.size(); }
		float kdtree_get_pt(size_t i, size_t dim) const { return dim == 0 ? x[i] : y[i]; }
		template <class BBox>
		bool kdtree_get_bbox(BBox&) const
		{
			return false;
		}
	};

   private:
	using TTree =
		nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, TCloud>, TCloud, 2, uint32_t>;
	std::unique_ptr<TCloud> m_bulk, m_recent;
	std::unique_ptr<TTree> m_bulkTree, m_recentTree;
	size_t m_firstLive = 0;
};

}  // namespace hslam::matching
