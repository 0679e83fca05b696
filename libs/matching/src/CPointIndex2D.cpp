/* hslam: 2D point cloud with k-d trees (see CPointIndex2D.h). */
#include <hslam/matching/CPointIndex2D.h>

#include <algorithm>
#include <limits>

namespace hslam::matching
{
namespace
{
/** nanoflann result set: the k nearest points with index >= firstLive, kept
 * sorted in (indices, distances2); a tree's index i is stored as i + offset.
 * Searching a second tree into the same set prunes it by the first's k-th
 * distance. */
class CLiveKnnResult
{
   public:
	CLiveKnnResult(size_t k, uint32_t* indices, float* distances2) : m_k(k), m_idx(indices), m_d2(distances2) {}
	/** The next tree's indices: those below firstLive are skipped, the others stored + offset. */
	void nextTree(uint32_t firstLive, uint32_t offset) { m_firstLive = firstLive, m_offset = offset; }
	size_t size() const { return m_count; }
	bool full() const { return m_count == m_k; }
	float worstDist() const { return full() ? m_d2[m_k - 1] : std::numeric_limits<float>::max(); }
	bool addPoint(float d2, uint32_t index)
	{
		if (index < m_firstLive || (full() && d2 >= m_d2[m_k - 1])) return true;
		size_t i = full() ? m_k - 1 : m_count++;
		for (; i > 0 && m_d2[i - 1] > d2; --i) m_d2[i] = m_d2[i - 1], m_idx[i] = m_idx[i - 1];
		m_d2[i] = d2, m_idx[i] = index + m_offset;
		return true;
	}

   private:
	size_t m_k, m_count = 0;
	uint32_t m_firstLive = 0, m_offset = 0;
	uint32_t* m_idx;
	float* m_d2;
};

std::unique_ptr<nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, CPointIndex2D::TCloud>,
													CPointIndex2D::TCloud, 2, uint32_t>>
treeOf(const CPointIndex2D::TCloud& cloud)
{
	using TTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, CPointIndex2D::TCloud>,
													  CPointIndex2D::TCloud, 2, uint32_t>;
	if (cloud.x.empty()) return nullptr;
	auto tree = std::make_unique<TTree>(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
	tree->buildIndex();
	return tree;
}
}  // namespace

CPointIndex2D::CPointIndex2D() : m_bulk(std::make_unique<TCloud>()), m_recent(std::make_unique<TCloud>()) {}
CPointIndex2D::~CPointIndex2D() = default;
CPointIndex2D::CPointIndex2D(CPointIndex2D&&) noexcept = default;
CPointIndex2D& CPointIndex2D::operator=(CPointIndex2D&&) noexcept = default;

void CPointIndex2D::build(std::vector<float> xs, std::vector<float> ys)
{
	m_bulkTree.reset(), m_recentTree.reset();
	m_bulk->x = std::move(xs), m_bulk->y = std::move(ys);
	m_recent->x.clear(), m_recent->y.clear();
	m_firstLive = 0;
	m_bulkTree = treeOf(*m_bulk);
}

void CPointIndex2D::append(const std::vector<float>& xs, const std::vector<float>& ys)
{
	m_recentTree.reset();
	m_recent->x.insert(m_recent->x.end(), xs.begin(), xs.end());
	m_recent->y.insert(m_recent->y.end(), ys.begin(), ys.end());
	m_recentTree = treeOf(*m_recent);
}

size_t CPointIndex2D::nearest(float x, float y, size_t k, uint32_t* indices, float* distances2) const
{
	k = std::min<size_t>(k, 32);
	if (k == 0) return 0;
	const float query[2] = {x, y};
	CLiveKnnResult result(k, indices, distances2);
	result.nextTree(static_cast<uint32_t>(m_firstLive), 0);
	if (m_bulkTree && m_firstLive < bulkSize()) m_bulkTree->findNeighbors(result, query, nanoflann::SearchParams());
	result.nextTree(0, static_cast<uint32_t>(bulkSize()));
	if (m_recentTree) m_recentTree->findNeighbors(result, query, nanoflann::SearchParams());
	return result.size();
}

}  // namespace hslam::matching
