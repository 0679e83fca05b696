#include "branch_and_bound.h"

#include <algorithm>
#include <array>

namespace hslam::graph::detail
{
namespace
{
/** One rotation's query cells split once for the whole window: points whose
 * cell stays inside the grid at every offset of the window are read without
 * bounds checks through a flat index, points outside at every offset are only
 * counted (they score 0), the rest are read with checks. */
struct TSplitQuery
{
	std::vector<int> flat;  //!< iy * width + ix of the always-inside points
	std::vector<int> cx, cy;  //!< cells of the points near the edge
	size_t count = 0;  //!< all points (the score's denominator)
};

TSplitQuery splitQuery(const CMultiResolutionGrid& grid, const TRotatedQuery& q, int w)
{
	TSplitQuery out;
	out.count = q.cx.size();
	const int W = grid.width(), H = grid.height();
	for (size_t i = 0; i < q.cx.size(); ++i)
	{
		const int x = q.cx[i], y = q.cy[i];
		if (x + w < 0 || y + w < 0 || x - w >= W || y - w >= H) continue;  // outside at every offset
		if (x - w >= 0 && y - w >= 0 && x + w < W && y + w < H)
			out.flat.push_back(y * W + x);
		else
			out.cx.push_back(x), out.cy.push_back(y);
	}
	return out;
}

/** Up to four children of a node, sorted by score (no allocation). */
struct TChildren
{
	std::array<TCandidate, 4> c;
	size_t n = 0;
	const TCandidate* begin() const { return c.data(); }
	const TCandidate* end() const { return c.data() + n; }
};

class CSearch
{
   public:
	CSearch(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations, int windowCells,
			const std::function<bool(int, int, int)>& excluded)
		: m_grid(grid), m_w(windowCells), m_excluded(excluded)
	{
		m_rot.reserve(rotations.size());
		for (const auto& q : rotations) m_rot.push_back(splitQuery(grid, q, windowCells));
	}

	/** Mean level value of the query of `c.rotation` shifted by (dx, dy), 0..1. */
	float score(const TCandidate& c)
	{
		++nodesScored;
		const auto& q = m_rot[static_cast<size_t>(c.rotation)];
		if (q.count == 0) return 0.f;
		const uint8_t* cells = m_grid.levelData(c.level) + (c.dy * m_grid.width() + c.dx);
		unsigned sum = 0;
		for (int f : q.flat) sum += cells[f];
		for (size_t i = 0; i < q.cx.size(); ++i) sum += m_grid.value(c.level, q.cx[i] + c.dx, q.cy[i] + c.dy);
		return static_cast<float>(sum) / (255.f * static_cast<float>(q.count));
	}

	std::vector<TCandidate> topLevel()
	{
		const int level = m_grid.levelCount() - 1, step = 1 << level;
		std::vector<TCandidate> out;
		for (int r = 0; r < static_cast<int>(m_rot.size()); ++r)
			for (int dx = -m_w; dx <= m_w; dx += step)
				for (int dy = -m_w; dy <= m_w; dy += step)
				{
					TCandidate c{r, dx, dy, level, 0.f};
					c.score = score(c);
					out.push_back(c);
				}
		std::sort(out.begin(), out.end(), byScore);
		return out;
	}

	/** Best leaf under the sorted candidates whose score beats `bound`. */
	template <class Range>
	TSearchResult search(const Range& candidates, float bound)
	{
		TSearchResult best;
		best.best.score = bound;
		for (const auto& c : candidates)
		{
			if (c.score <= best.best.score) break;  // sorted: nothing below can win
			if (c.level == 0)
			{
				if (m_excluded && m_excluded(c.rotation, c.dx, c.dy)) continue;
				best.found = true, best.best = c;
				continue;
			}
			const auto sub = search(children(c), best.best.score);
			if (sub.found) best = sub;
		}
		return best;
	}

	size_t nodesScored = 0;

   private:
	TChildren children(const TCandidate& c)
	{
		const int half = 1 << (c.level - 1);
		TChildren out;
		for (int ox : {0, half})
			for (int oy : {0, half})
			{
				TCandidate child{c.rotation, c.dx + ox, c.dy + oy, c.level - 1, 0.f};
				if (child.dx > m_w || child.dy > m_w) continue;
				child.score = score(child);
				size_t i = out.n++;  // insertion sort, stable like std::sort on so few
				for (; i > 0 && byScore(child, out.c[i - 1]); --i) out.c[i] = out.c[i - 1];
				out.c[i] = child;
			}
		return out;
	}

	static bool byScore(const TCandidate& a, const TCandidate& b) { return a.score > b.score; }

	const CMultiResolutionGrid& m_grid;
	std::vector<TSplitQuery> m_rot;
	int m_w;
	const std::function<bool(int, int, int)>& m_excluded;
};
}  // namespace

TSearchResult branchAndBound(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations,
							 int windowCells, float minScore, const std::function<bool(int, int, int)>& excluded)
{
	CSearch s(grid, rotations, windowCells, excluded);
	auto result = s.search(s.topLevel(), minScore);
	result.nodesScored = s.nodesScored;
	return result;
}

}  // namespace hslam::graph::detail
