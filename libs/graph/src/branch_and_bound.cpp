#include "branch_and_bound.h"

#include <algorithm>

namespace hslam::graph::detail
{
namespace
{
class CSearch
{
   public:
	CSearch(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations, int windowCells,
			const std::function<bool(int, int, int)>& excluded)
		: m_grid(grid), m_rot(rotations), m_w(windowCells), m_excluded(excluded)
	{
	}

	/** Mean level value of the query of `c.rotation` shifted by (dx, dy), 0..1. */
	float score(const TCandidate& c)
	{
		++nodesScored;
		const auto& q = m_rot[static_cast<size_t>(c.rotation)];
		unsigned sum = 0;
		for (size_t i = 0; i < q.cx.size(); ++i) sum += m_grid.value(c.level, q.cx[i] + c.dx, q.cy[i] + c.dy);
		return q.cx.empty() ? 0.f : static_cast<float>(sum) / (255.f * static_cast<float>(q.cx.size()));
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
		sortByScore(out);
		return out;
	}

	/** Best leaf under the sorted candidates whose score beats `bound`. */
	TSearchResult search(const std::vector<TCandidate>& candidates, float bound)
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
	std::vector<TCandidate> children(const TCandidate& c)
	{
		const int half = 1 << (c.level - 1);
		std::vector<TCandidate> out;
		for (int ox : {0, half})
			for (int oy : {0, half})
			{
				TCandidate child{c.rotation, c.dx + ox, c.dy + oy, c.level - 1, 0.f};
				if (child.dx > m_w || child.dy > m_w) continue;
				child.score = score(child);
				out.push_back(child);
			}
		sortByScore(out);
		return out;
	}

	static void sortByScore(std::vector<TCandidate>& v)
	{
		std::sort(v.begin(), v.end(), [](const TCandidate& a, const TCandidate& b) { return a.score > b.score; });
	}

	const CMultiResolutionGrid& m_grid;
	const std::vector<TRotatedQuery>& m_rot;
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
