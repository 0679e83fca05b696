#include "branch_and_bound.h"

#include <algorithm>
#include <array>
#include <cmath>

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
	out.flat.reserve(q.cx.size());  // most points are inside: one allocation, not a doubling series
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

/** Rotations are branched on too (beyond Hess et al.): a top node covers a
 * group of 2 g + 1 consecutive rotations and a block of 2^(top - 1) offsets.
 * The rotation step moves the farthest query point by at most one cell
 * (chords add up), so from the group's middle rotation every point of a
 * member rotation lies at most g cells away (g + 1 with the rounding to
 * cells): the top level's pool of 2^top = 2^(top - 1) + 2 (g + 1) cells,
 * read g + 1 cells before the block, bounds every member and offset. One top
 * node replaces 2 g + 1 per-rotation ones, and a rotation is only prepared
 * (cells split) when its group is expanded. */
struct TGrouping
{
	int g = 0;  //!< half-width of a rotation group (0: no grouping)
	int block = 1;  //!< offsets per top node and axis
};

TGrouping groupingFor(int topLevel, size_t rotationCount)
{
	if (topLevel < 3 || rotationCount < 3) return {0, 1 << topLevel};
	const int block = 1 << (topLevel - 1);
	return {block / 2 - 1, block};
}

class CSearch
{
   public:
	CSearch(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations, const TRotationFiller& fill,
			int windowCells, const std::function<bool(int, int, int)>& excluded, bool firstAbove)
		: m_grid(grid),
		  m_queries(rotations),
		  m_fill(fill),
		  m_w(windowCells),
		  m_excluded(excluded),
		  m_firstAbove(firstAbove),
		  m_group(groupingFor(grid.levelCount() - 1, rotations.size())),
		  m_rot(rotations.size()),
		  m_split(rotations.size(), false)
	{
	}

	/** Mean level value of the query of `c.rotation` shifted by (dx, dy), 0..1
	 * (a group node: the bound of all its rotations and offsets). */
	float score(const TCandidate& c, float bound, bool group = false)
	{
		float value = 0.f;
		scoreNodes<1>(&c, 1, bound, group ? m_group.g + 1 : 0, &value);
		return value;
	}

	/** Top nodes, sorted by bound: rotation groups (rotation = the middle
	 * one) or, without grouping, single rotations. */
	std::vector<TCandidate> topLevel(float bound)
	{
		const int level = m_grid.levelCount() - 1, n = static_cast<int>(m_queries.size());
		const int step = m_group.g > 0 ? 2 * m_group.g + 1 : 1, first = m_group.g > 0 ? m_group.g : 0;
		std::vector<TCandidate> out;
		for (int r = first; r - m_group.g < n; r += step)
			for (int dx = -m_w; dx <= m_w; dx += m_group.block)
				for (int dy = -m_w; dy <= m_w; dy += m_group.block)
				{
					// the last group's middle may lie past the end: it is centred on
					// the last rotation and shares a few members with the one before
					TCandidate c{std::min(r, n - 1), dx, dy, level, 0.f};
					c.score = score(c, bound, m_group.g > 0);
					out.push_back(c);
				}
		std::sort(out.begin(), out.end(), byScore);
		return out;
	}

	/** Best leaf under the sorted candidates whose score beats `bound`. */
	template <class Range>
	TSearchResult search(const Range& candidates, float bound, bool groups = false)
	{
		TSearchResult best;
		best.best.score = bound;
		for (const auto& c : candidates)
		{
			if (c.score <= best.best.score) break;  // sorted: nothing below can win
			if (c.level == 0 && !groups)
			{
				if (m_excluded && m_excluded(c.rotation, c.dx, c.dy)) continue;
				best.found = true, best.best = c;
				if (m_firstAbove) return best;
				continue;
			}
			if (whollyExcluded(c, groups)) continue;  // no leaf below it may be returned
			const auto sub = groups ? search(members(c, best.best.score), best.best.score)
									: search(children(c, best.best.score), best.best.score);
			if (sub.found) best = sub;
			if (sub.found && m_firstAbove) return best;
		}
		return best;
	}

	bool grouped() const { return m_group.g > 0; }
	size_t nodesScored = 0;

   private:
	/** Whether every leaf under `c` is excluded. The excluded leaves of a
	 * rotation form a disc of offsets and those of an offset an interval of
	 * rotations (CCorrelativeScanMatcher's exclusion), so the corners of the
	 * node's block at its first and last rotation decide for all of them.
	 * Without this, the search for a second peak descended through the
	 * first peak's own neighbourhood, the highest-scoring part of the window,
	 * only to skip every leaf there. */
	bool whollyExcluded(const TCandidate& c, bool group) const
	{
		if (!m_excluded) return false;
		const int n = static_cast<int>(m_queries.size());
		const int r0 = group ? std::max(0, c.rotation - m_group.g) : c.rotation;
		const int r1 = group ? std::min(n - 1, c.rotation + m_group.g) : c.rotation;
		const int size = group ? m_group.block : 1 << c.level;
		const int x1 = std::min(c.dx + size - 1, m_w), y1 = std::min(c.dy + size - 1, m_w);
		for (int r : {r0, r1})
			for (int x : {c.dx, x1})
				for (int y : {c.dy, y1})
					if (!m_excluded(r, x, y)) return false;
		return true;
	}

	const TSplitQuery& split(int rotation)
	{
		const auto r = static_cast<size_t>(rotation);
		if (m_split[r]) return m_rot[r];
		const TRotatedQuery* q = &m_queries[r];
		if (m_fill) m_scratch.yaw_rad = q->yaw_rad, m_fill(m_scratch), q = &m_scratch;
		m_rot[r] = splitQuery(m_grid, *q, m_w + m_group.g + 1), m_split[r] = true;
		return m_rot[r];
	}

	/** The single rotations of a group node, at the level below, sorted. */
	std::vector<TCandidate> members(const TCandidate& group, float bound)
	{
		const int n = static_cast<int>(m_queries.size());
		std::vector<TCandidate> out;
		for (int r = std::max(0, group.rotation - m_group.g); r <= std::min(n - 1, group.rotation + m_group.g); ++r)
		{
			TCandidate c{r, group.dx, group.dy, group.level - 1, 0.f};
			c.score = score(c, bound);
			out.push_back(c);
		}
		std::stable_sort(out.begin(), out.end(), byScore);
		return out;
	}

	TChildren children(const TCandidate& c, float bound)
	{
		const int half = 1 << (c.level - 1);
		std::array<TCandidate, 4> kids;
		size_t n = 0;
		for (int ox : {0, half})
			for (int oy : {0, half})
			{
				const TCandidate child{c.rotation, c.dx + ox, c.dy + oy, c.level - 1, 0.f};
				if (child.dx <= m_w && child.dy <= m_w) kids[n++] = child;
			}
		std::array<float, 4> scores{};
		scoreNodes<4>(kids.data(), n, bound, 0, scores.data());
		TChildren out;
		for (size_t k = 0; k < n; ++k)
		{
			kids[k].score = scores[k];
			size_t i = out.n++;  // insertion sort, stable like std::sort on so few
			for (; i > 0 && byScore(kids[k], out.c[i - 1]); --i) out.c[i] = out.c[i - 1];
			out.c[i] = kids[k];
		}
		return out;
	}

	/** score() of up to N nodes of one rotation and level (their offsets
	 * moved back by `shift` cells) in one pass over its points: siblings'
	 * cells lie within 2^level of each other, on the same cache lines at the
	 * finest levels. A node's summing stops once it cannot score above
	 * `bound` even if every point left scored 255: such a node is pruned
	 * whatever its exact score, so the search visits the same nodes (the
	 * value given is then <= bound); a node that can is summed over every
	 * point, to the bit. */
	template <size_t N>
	void scoreNodes(const TCandidate* nodes, size_t n, float bound, int shift, float* out)
	{
		nodesScored += n;
		const auto& q = split(nodes[0].rotation);
		if (q.count == 0) return std::fill(out, out + n, 0.f);
		const uint8_t* cells = m_grid.levelData(nodes[0].level);
		std::array<ptrdiff_t, N> offset{};  // absent nodes read the first one's cells, unused
		for (size_t k = 0; k < N; ++k)
		{
			const TCandidate& c = nodes[k < n ? k : 0];
			offset[k] = static_cast<ptrdiff_t>(c.dy - shift) * m_grid.width() + (c.dx - shift);
		}
		const float scale = 255.f * static_cast<float>(q.count);
		// the sum a node must exceed, as an integer: sum > need <=> score > bound
		const long need = static_cast<long>(std::floor(static_cast<double>(bound) * scale));
		std::array<long, N> sum{};
		std::array<bool, N> done{};
		long left = 255L * static_cast<long>(q.count);
		size_t open = n;
		constexpr size_t kChunk = 32;
		for (size_t i = 0; i < q.flat.size() && open > 0; i += kChunk)
		{
			const size_t end = std::min(q.flat.size(), i + kChunk);
			std::array<unsigned, N> part{};
			for (size_t j = i; j < end; ++j)
				for (size_t k = 0; k < N; ++k) part[k] += cells[q.flat[j] + offset[k]];
			left -= 255L * static_cast<long>(end - i);
			for (size_t k = 0; k < n; ++k)
				if (!done[k] && (sum[k] += part[k]) + left <= need)
					done[k] = true, --open, out[k] = static_cast<float>(sum[k] + left) / scale;
		}
		for (size_t k = 0; k < n; ++k)
		{
			if (done[k]) continue;
			const int dx = nodes[k].dx - shift, dy = nodes[k].dy - shift;
			for (size_t i = 0; i < q.cx.size(); ++i) sum[k] += m_grid.value(nodes[k].level, q.cx[i] + dx, q.cy[i] + dy);
			out[k] = static_cast<float>(sum[k]) / scale;
		}
	}

	static bool byScore(const TCandidate& a, const TCandidate& b) { return a.score > b.score; }

	const CMultiResolutionGrid& m_grid;
	const std::vector<TRotatedQuery>& m_queries;
	const TRotationFiller& m_fill;  //!< empty: the rotations came filled
	TRotatedQuery m_scratch;  //!< the rotation being filled
	int m_w;
	const std::function<bool(int, int, int)>& m_excluded;
	bool m_firstAbove;  //!< stop at the first leaf above the bound (an existence test)
	TGrouping m_group;
	std::vector<TSplitQuery> m_rot;
	std::vector<bool> m_split;
};
}  // namespace

TSearchResult branchAndBound(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations,
							 int windowCells, float minScore, const std::function<bool(int, int, int)>& excluded,
							 bool firstAbove)
{
	return branchAndBound(grid, rotations, TRotationFiller(), windowCells, minScore, excluded, firstAbove);
}

TSearchResult branchAndBound(const CMultiResolutionGrid& grid, const std::vector<TRotatedQuery>& rotations,
							 const TRotationFiller& fill, int windowCells, float minScore,
							 const std::function<bool(int, int, int)>& excluded, bool firstAbove)
{
	CSearch s(grid, rotations, fill, windowCells, excluded, firstAbove);
	// A search for the best leaf starts from the score of the window's centre
	// (the guess): nodes that cannot beat it are pruned from the start
	// instead of after the first descent. The bound is just below that score,
	// so the centre leaf itself or a better one is found, and the search
	// visits the nodes it visited from minScore in the same order: the same
	// leaf is returned (ties included). Not for an existence test or a
	// search with exclusions (a second peak must not be the first one).
	float bound = minScore;
	if (!excluded && !firstAbove && !rotations.empty())
	{
		const detail::TCandidate centre{static_cast<int>(rotations.size() / 2), 0, 0, 0, 0.f};
		const float centreScore = s.score(centre, minScore);
		if (centreScore > minScore) bound = std::nextafter(centreScore, 0.f);
	}
	auto result = s.search(s.topLevel(bound), bound, s.grouped());
	result.nodesScored = s.nodesScored;
	return result;
}

}  // namespace hslam::graph::detail
