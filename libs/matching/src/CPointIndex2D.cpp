/* hslam: 2D point cloud with a bucket grid (see CPointIndex2D.h). */
#include <hslam/matching/CPointIndex2D.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::matching
{
namespace
{
/** Cell side (m). Scan points lie on the reference's walls: with 0.25 m the
 * k nearest (k <= 6 in ICP and its covariance) are usually in the query's
 * cell and the ring around it. */
constexpr float kCell_m = 0.25f;
/** Cells at most; a wider cloud (far stray returns) gets larger cells. */
constexpr double kMaxCells = 1 << 22;

/** The k nearest offered points, sorted by (distance, index). */
class CKnnResult
{
   public:
	CKnnResult(size_t k, uint32_t* indices, float* distances2) : m_k(k), m_idx(indices), m_d2(distances2) {}
	size_t size() const { return m_count; }
	bool full() const { return m_count == m_k; }
	float worst() const { return full() ? m_d2[m_k - 1] : std::numeric_limits<float>::max(); }
	void offer(float d2, uint32_t index)
	{
		if (full() && !before(d2, index, m_d2[m_k - 1], m_idx[m_k - 1])) return;
		size_t i = full() ? m_k - 1 : m_count++;
		for (; i > 0 && before(d2, index, m_d2[i - 1], m_idx[i - 1]); --i) m_d2[i] = m_d2[i - 1], m_idx[i] = m_idx[i - 1];
		m_d2[i] = d2, m_idx[i] = index;
	}

   private:
	static bool before(float d2, uint32_t i, float e2, uint32_t j) { return d2 < e2 || (d2 == e2 && i < j); }
	size_t m_k, m_count = 0;
	uint32_t* m_idx;
	float* m_d2;
};
}  // namespace

void CPointIndex2D::build(std::vector<float> xs, std::vector<float> ys)
{
	m_x = std::move(xs), m_y = std::move(ys);
	m_bulkSize = m_x.size(), m_firstLive = 0;
	rebuildGrid();
}

void CPointIndex2D::append(const std::vector<float>& xs, const std::vector<float>& ys)
{
	m_x.insert(m_x.end(), xs.begin(), xs.end());
	m_y.insert(m_y.end(), ys.begin(), ys.end());
	rebuildGrid();
}

void CPointIndex2D::rebuildGrid()
{
	m_width = m_height = 0;
	m_cellStart.clear(), m_sortedX.clear(), m_sortedY.clear(), m_sortedIndex.clear();
	if (empty()) return;
	float minX = m_x[m_firstLive], maxX = minX, minY = m_y[m_firstLive], maxY = minY;
	for (size_t i = m_firstLive; i < size(); ++i)
		minX = std::min(minX, m_x[i]), maxX = std::max(maxX, m_x[i]), minY = std::min(minY, m_y[i]),
		maxY = std::max(maxY, m_y[i]);
	m_cell_m = kCell_m;
	const double spanCells = (static_cast<double>(maxX) - minX) * (static_cast<double>(maxY) - minY) / (m_cell_m * m_cell_m);
	if (spanCells > kMaxCells) m_cell_m = static_cast<float>(m_cell_m * std::sqrt(spanCells / kMaxCells));
	m_invCell = 1.f / m_cell_m;
	m_x0 = minX, m_y0 = minY;
	m_width = static_cast<int>((maxX - minX) * m_invCell) + 1;
	m_height = static_cast<int>((maxY - minY) * m_invCell) + 1;
	// counting sort of the live points by cell
	const size_t cells = static_cast<size_t>(m_width) * static_cast<size_t>(m_height);
	m_cellStart.assign(cells + 1, 0);
	m_cellOf.resize(liveSize());
	for (size_t i = m_firstLive; i < size(); ++i)
	{
		const int ix = std::min(m_width - 1, static_cast<int>((m_x[i] - m_x0) * m_invCell));
		const int iy = std::min(m_height - 1, static_cast<int>((m_y[i] - m_y0) * m_invCell));
		const uint32_t c = static_cast<uint32_t>(iy * m_width + ix);
		m_cellOf[i - m_firstLive] = c;
		++m_cellStart[c + 1];
	}
	for (size_t c = 0; c < cells; ++c) m_cellStart[c + 1] += m_cellStart[c];
	m_sortedX.resize(liveSize()), m_sortedY.resize(liveSize()), m_sortedIndex.resize(liveSize());
	m_next.assign(m_cellStart.begin(), m_cellStart.end() - 1);
	for (size_t i = m_firstLive; i < size(); ++i)  // in index order: a cell's entries stay sorted by index
	{
		const uint32_t slot = m_next[m_cellOf[i - m_firstLive]]++;
		m_sortedX[slot] = m_x[i], m_sortedY[slot] = m_y[i], m_sortedIndex[slot] = static_cast<uint32_t>(i);
	}
}

template <class Result>
void CPointIndex2D::scanCell(int ix, int iy, float x, float y, Result& result) const
{
	const size_t c = static_cast<size_t>(iy) * static_cast<size_t>(m_width) + static_cast<size_t>(ix);
	const uint32_t begin = m_cellStart[c], end = m_cellStart[c + 1];
	if (begin == end) return;  // most cells of a ring are empty (walls are thin)
	if (result.full())  // a cell wholly farther than the k-th point found cannot add one
	{
		const float cx0 = m_x0 + static_cast<float>(ix) * m_cell_m, cy0 = m_y0 + static_cast<float>(iy) * m_cell_m;
		const float ex = std::max(0.f, std::max(cx0 - x, x - (cx0 + m_cell_m)));
		const float ey = std::max(0.f, std::max(cy0 - y, y - (cy0 + m_cell_m)));
		if (ex * ex + ey * ey > result.worst()) return;
	}
	for (uint32_t s = begin; s < end; ++s)
	{
		if (m_sortedIndex[s] < m_firstLive) continue;  // retired since the grid was built
		const float dx = m_sortedX[s] - x, dy = m_sortedY[s] - y;
		result.offer(dx * dx + dy * dy, m_sortedIndex[s]);
	}
}

size_t CPointIndex2D::nearest(float x, float y, size_t k, uint32_t* indices, float* distances2) const
{
	float exact_m = 0;
	return nearestWithin(x, y, k, std::numeric_limits<float>::infinity(), indices, distances2, exact_m);
}

size_t CPointIndex2D::nearestWithin(float x, float y, size_t k, float max_m, uint32_t* indices, float* distances2,
									float& exact_m) const
{
	exact_m = std::numeric_limits<float>::infinity();
	k = std::min<size_t>(k, 32);
	if (k == 0 || m_width == 0) return 0;
	CKnnResult result(k, indices, distances2);
	// the query's cell, clamped to a range that keeps the ring arithmetic in int
	const float fx = std::clamp((x - m_x0) * m_invCell, -1e6f, 1e6f), fy = std::clamp((y - m_y0) * m_invCell, -1e6f, 1e6f);
	const int cx = static_cast<int>(std::floor(fx)), cy = static_cast<int>(std::floor(fy));
	// rings wholly outside the grid hold nothing: start at the first that reaches it
	const int gapX = cx < 0 ? -cx : std::max(0, cx - (m_width - 1));
	const int gapY = cy < 0 ? -cy : std::max(0, cy - (m_height - 1));
	for (int r = std::max(gapX, gapY);; ++r)
	{
		scanRing(cx, cy, r, x, y, result);
		if (cx - r <= 0 && cy - r <= 0 && cx + r >= m_width - 1 && cy + r >= m_height - 1) break;  // grid covered
		// any point outside the (2r + 1)^2 block lies at least this far away
		const float reach = std::min(std::min(fx - static_cast<float>(cx - r), static_cast<float>(cx + r + 1) - fx),
									 std::min(fy - static_cast<float>(cy - r), static_cast<float>(cy + r + 1) - fy)) *
							m_cell_m;
		if (result.full() && reach > 0 && result.worst() <= reach * reach) break;
		if (reach >= max_m)  // every point within max_m has been offered
		{
			exact_m = reach;
			break;
		}
	}
	return result.size();
}

template <class Result>
void CPointIndex2D::scanRing(int cx, int cy, int r, float x, float y, Result& result) const
{
	const int x0 = std::max(0, cx - r), x1 = std::min(m_width - 1, cx + r);
	const int y0 = std::max(0, cy - r), y1 = std::min(m_height - 1, cy + r);
	for (int iy = y0; iy <= y1; ++iy)
	{
		if (iy == cy - r || iy == cy + r)  // a full row of the ring
			for (int ix = x0; ix <= x1; ++ix) scanCell(ix, iy, x, y, result);
		else  // only the ring's two side cells
		{
			if (cx - r >= 0 && cx - r < m_width) scanCell(cx - r, iy, x, y, result);
			if (cx + r >= 0 && cx + r < m_width) scanCell(cx + r, iy, x, y, result);
		}
	}
}

}  // namespace hslam::matching
