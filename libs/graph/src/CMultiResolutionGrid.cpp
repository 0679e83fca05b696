#include <hslam/graph/CMultiResolutionGrid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hslam::graph
{
void CMultiResolutionGrid::build(const std::vector<mrpt::math::TPoint2Df>& points, double resolution_m,
								 double kernelSigma_m, int levels)
{
	if (resolution_m <= 0 || levels < 1) throw std::invalid_argument("CMultiResolutionGrid: bad resolution or levels");
	m_levels.clear();
	m_res = resolution_m;
	if (points.empty()) return;
	float minX = points[0].x, maxX = points[0].x, minY = points[0].y, maxY = points[0].y;
	for (const auto& p : points)
	{
		minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
		minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
	}
	const int kernelCells = static_cast<int>(std::ceil(3.0 * kernelSigma_m / m_res));
	const int margin = (1 << (levels - 1)) + kernelCells + 1;
	m_x0 = minX - margin * m_res;
	m_y0 = minY - margin * m_res;
	m_width = static_cast<int>(std::ceil((maxX - minX) / m_res)) + 2 * margin + 1;
	m_height = static_cast<int>(std::ceil((maxY - minY) / m_res)) + 2 * margin + 1;
	m_levels.emplace_back(static_cast<size_t>(m_width) * m_height, uint8_t{0});
	stampPoints(points, kernelSigma_m);
	for (int level = 1; level < levels; ++level) addMaxPooledLevel(level);
}

void CMultiResolutionGrid::stampPoints(const std::vector<mrpt::math::TPoint2Df>& points, double kernelSigma_m)
{
	const double sigma = std::max(kernelSigma_m, 1e-3);
	const int k = static_cast<int>(std::ceil(3.0 * sigma / m_res));
	auto& cells = m_levels[0];
	for (const auto& p : points)
	{
		const int cx = cellX(p.x), cy = cellY(p.y);
		for (int dy = -k; dy <= k; ++dy)
			for (int dx = -k; dx <= k; ++dx)
			{
				const int ix = cx + dx, iy = cy + dy;
				// distance from the point to the centre of cell (ix, iy)
				const double ex = m_x0 + (ix + 0.5) * m_res - p.x, ey = m_y0 + (iy + 0.5) * m_res - p.y;
				const double d2 = ex * ex + ey * ey;
				if (d2 > 9.0 * sigma * sigma) continue;
				const auto v = static_cast<uint8_t>(std::lround(255.0 * std::exp(-0.5 * d2 / (sigma * sigma))));
				auto& cell = cells[static_cast<size_t>(iy) * m_width + ix];
				cell = std::max(cell, v);
			}
	}
}

void CMultiResolutionGrid::addMaxPooledLevel(int level)
{
	// max over [x, x + 2^level) is the max of two blocks of 2^(level-1), in x then in y
	const int half = 1 << (level - 1);
	const auto& prev = m_levels.back();
	std::vector<uint8_t> rows(prev.size(), 0), next(prev.size(), 0);
	for (int iy = 0; iy < m_height; ++iy)
		for (int ix = 0; ix < m_width; ++ix)
		{
			const size_t i = static_cast<size_t>(iy) * m_width + ix;
			rows[i] = ix + half < m_width ? std::max(prev[i], prev[i + half]) : prev[i];
		}
	for (int iy = 0; iy < m_height; ++iy)
		for (int ix = 0; ix < m_width; ++ix)
		{
			const size_t i = static_cast<size_t>(iy) * m_width + ix;
			next[i] = iy + half < m_height ? std::max(rows[i], rows[i + static_cast<size_t>(half) * m_width]) : rows[i];
		}
	m_levels.push_back(std::move(next));
}

}  // namespace hslam::graph
