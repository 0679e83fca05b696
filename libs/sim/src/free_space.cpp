/* hslam sim: CFreeSpaceGrid (see free_space.h). */
#include <hslam/sim/clearance.h>
#include <hslam/sim/free_space.h>

#include <cmath>
#include <functional>
#include <queue>

namespace hslam::sim
{
CFreeSpaceGrid::CFreeSpaceGrid(const CWorld& world, const mrpt::math::TPoint2D& seed, double clearance, double cell)
	: m_cell(cell)
{
	const auto b = world.bounds();
	m_x0 = b.min_x;
	m_y0 = b.min_y;
	m_w = static_cast<int>(std::ceil((b.max_x - b.min_x) / cell)) + 1;
	m_h = static_cast<int>(std::ceil((b.max_y - b.min_y) / cell)) + 1;
	std::vector<char> clear(static_cast<size_t>(m_w) * m_h);
	for (int i = 0; i < static_cast<int>(clear.size()); ++i) clear[i] = clearance_m(world, centre(i)) >= clearance;
	m_free.assign(clear.size(), 0);
	const int s = index(seed);
	if (s < 0 || !clear[s]) return;
	std::vector<int> stack{s};  // flood fill from the seed
	m_free[s] = 1;
	while (!stack.empty())
	{
		const int c = stack.back();
		stack.pop_back();
		for (const auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
		{
			const int i = c % m_w + di, j = c / m_w + dj;
			if (i < 0 || j < 0 || i >= m_w || j >= m_h || !clear[j * m_w + i] || m_free[j * m_w + i]) continue;
			m_free[j * m_w + i] = 1;
			stack.push_back(j * m_w + i);
		}
	}
}

int CFreeSpaceGrid::index(const mrpt::math::TPoint2D& p) const
{
	const int i = static_cast<int>(std::floor((p.x - m_x0) / m_cell)), j = static_cast<int>(std::floor((p.y - m_y0) / m_cell));
	return (i < 0 || j < 0 || i >= m_w || j >= m_h) ? -1 : j * m_w + i;
}

mrpt::math::TPoint2D CFreeSpaceGrid::centre(int idx) const
{
	return {m_x0 + (idx % m_w + 0.5) * m_cell, m_y0 + (idx / m_w + 0.5) * m_cell};
}

bool CFreeSpaceGrid::isFree(const mrpt::math::TPoint2D& p) const
{
	const int k = index(p);
	return k >= 0 && m_free[k];
}

std::vector<mrpt::math::TPoint2D> CFreeSpaceGrid::freeCells() const
{
	std::vector<mrpt::math::TPoint2D> out;
	for (int k = 0; k < static_cast<int>(m_free.size()); ++k)
		if (m_free[k]) out.push_back(centre(k));
	return out;
}

double CFreeSpaceGrid::shortestPath_m(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) const
{
	const int start = index(a), goal = index(b);
	if (start < 0 || goal < 0) return std::nan("");
	std::vector<double> dist(m_free.size(), 1e18);
	using TItem = std::pair<double, int>;
	std::priority_queue<TItem, std::vector<TItem>, std::greater<>> open;
	dist[start] = 0;
	open.push({0, start});
	while (!open.empty())
	{
		const auto [d, c] = open.top();
		open.pop();
		if (c == goal) return d;
		if (d > dist[c]) continue;
		for (int dj = -1; dj <= 1; ++dj)
			for (int di = -1; di <= 1; ++di)
			{
				const int i = c % m_w + di, j = c / m_w + dj, n = j * m_w + i;
				if ((!di && !dj) || i < 0 || j < 0 || i >= m_w || j >= m_h || (!m_free[n] && n != goal)) continue;
				const double nd = d + m_cell * std::hypot(di, dj);
				if (nd < dist[n]) dist[n] = nd, open.push({nd, n});
			}
	}
	return std::nan("");
}
}  // namespace hslam::sim
