/* hslam: a 2D point cloud with exact k-nearest-neighbour queries through a
 * uniform bucket grid: the reference of CPointToPointIcp and of the
 * geometric ICP covariance.
 *
 * Why a grid and not a k-d tree: ICP's queries are scan points lying on the
 * walls the reference samples, so their nearest neighbours sit in the
 * query's own cell or the ring around it. A bucket grid answers those by
 * reading a few contiguous cells, and it is built in O(n) by a counting sort
 * (no tree to balance). Replacing nanoflann's k-d tree (Debian
 * libnanoflann-dev) here cut the front-end's tree-query and tree-build time
 * (docs/pose-estimation.md, "Bucket-grid nearest neighbours"); answers are the
 * same exact k nearest points.
 *
 * A scan-to-map reference changes a little at every keyframe (one keyframe
 * in, the oldest out). Points are kept in two parts for the caller's
 * bookkeeping: a bulk part (build()) and a recent part (append()); indices
 * address the bulk part first, then the recent part. Points at the front of
 * the bulk part can be retired (a keyframe leaving the window) without
 * rebuilding: queries skip them. Every build() or append() re-sorts the live
 * points into the grid (linear time). */
#pragma once

#include <cstdint>
#include <vector>

namespace hslam::matching
{
class CPointIndex2D
{
   public:
	/** Replaces all points (into the bulk part) and rebuilds. */
	void build(std::vector<float> xs, std::vector<float> ys);
	/** Adds points to the recent part and rebuilds the grid. */
	void append(const std::vector<float>& xs, const std::vector<float>& ys);
	/** Bulk points with an index below `firstLive` are skipped from now on. */
	void retireBelow(size_t firstLive) { m_firstLive = firstLive; }

	bool empty() const { return liveSize() == 0; }
	/** Addressable points (bulk, retired ones included, then recent). */
	size_t size() const { return m_x.size(); }
	size_t liveSize() const { return size() - m_firstLive; }
	size_t bulkSize() const { return m_bulkSize; }
	size_t recentSize() const { return size() - m_bulkSize; }
	float x(size_t i) const { return m_x[i]; }
	float y(size_t i) const { return m_y[i]; }

	/** Up to k (<= 32) nearest live points of (x, y): indices and squared
	 * distances, nearest first (equal distances: lower index first). Returns
	 * how many were found (k unless fewer points are live). */
	size_t nearest(float x, float y, size_t k, uint32_t* indices, float* distances2) const;
	/** As nearest(), but the search stops once every live point within
	 * max_m of (x, y) has been seen. exact_m is set to a radius within which
	 * the answer is exact: every live point nearer than exact_m is among the
	 * results, in order (infinity when the search did not stop early, i.e.
	 * the answer is nearest()'s). exact_m >= max_m when it stopped early;
	 * results at exact_m or beyond may not be the true nearest. ICP's pairing
	 * uses it: a point with nothing within its pairing distance is unpaired
	 * however far its true nearest point is. */
	size_t nearestWithin(float x, float y, size_t k, float max_m, uint32_t* indices, float* distances2,
						 float& exact_m) const;

   private:
	void rebuildGrid();
	/** Offers the cells of the square ring of radius r (cells) around (cx, cy). */
	template <class Result>
	void scanRing(int cx, int cy, int r, float x, float y, Result& result) const;
	/** Offers the live points of cell (ix, iy) to the result. */
	template <class Result>
	void scanCell(int ix, int iy, float x, float y, Result& result) const;

	std::vector<float> m_x, m_y;  //!< all points, by index
	size_t m_bulkSize = 0, m_firstLive = 0;
	// the grid: cell (ix, iy) holds entries [m_cellStart[c], m_cellStart[c + 1])
	// of the cell-ordered copies below, c = iy * m_width + ix
	float m_x0 = 0, m_y0 = 0, m_cell_m = 0.25f, m_invCell = 4.f;
	int m_width = 0, m_height = 0;
	std::vector<uint32_t> m_cellStart;
	std::vector<float> m_sortedX, m_sortedY;
	std::vector<uint32_t> m_sortedIndex;
	std::vector<uint32_t> m_cellOf, m_next;  //!< rebuildGrid()'s scratch, kept between rebuilds
};

}  // namespace hslam::matching
