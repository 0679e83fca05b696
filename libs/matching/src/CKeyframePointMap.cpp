#include <hslam/common/cell_key.h>
#include <hslam/fusion/se2.h>
#include <hslam/matching/CKeyframePointMap.h>

#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace hslam::matching
{
bool CKeyframePointMap::wantsKeyframe(const mrpt::poses::CPose2D& pose, double spacing) const
{
	if (m_keyframes.empty()) return true;
	const auto& last = m_keyframes.back().pose;
	return pose.distanceTo(last) >= spacing * m_options.insertion_distance_m ||
		   std::abs(fusion::wrapToPi(pose.phi() - last.phi())) >= spacing * m_options.insertion_angle_rad;
}

void CKeyframePointMap::addKeyframe(const mrpt::poses::CPose2D& pose, const std::vector<mrpt::math::TPoint2D>& points)
{
	TKeyframe k;
	k.pose = pose;
	k.worldPoints.reserve(points.size());
	const double spacing2 = m_options.min_point_spacing_m * m_options.min_point_spacing_m;
	for (const auto& p : points)
	{
		const auto w = pose + p;
		if (!k.worldPoints.empty())
		{
			const auto d = w - k.worldPoints.back();
			if (d.x * d.x + d.y * d.y < spacing2) continue;
		}
		k.worldPoints.push_back(w);
	}
	m_keyframes.push_back(std::move(k));
	++m_nextId;
	if (m_options.max_keyframes > 0 && m_keyframes.size() > static_cast<size_t>(m_options.max_keyframes))
	{
		m_keyframes.pop_front();
		++m_firstId;
	}
}

bool CKeyframePointMap::updateWindow(const mrpt::poses::CPose2D& robotPose)
{
	std::vector<size_t> window;
	for (size_t i = 0; i < m_keyframes.size(); ++i)
		if (m_options.radius_m <= 0 || m_keyframes[i].pose.distanceTo(robotPose) <= m_options.radius_m)
			window.push_back(m_firstId + i);
	if (window == m_windowIds) return false;
	m_windowIds = std::move(window);
	m_referenceStale = m_indexStale = true;
	return true;
}

const mrpt::maps::CSimplePointsMap& CKeyframePointMap::reference(const mrpt::poses::CPose2D& robotPose)
{
	updateWindow(robotPose);
	if (!m_referenceStale) return m_reference;
	m_referenceStale = false;
	std::vector<float> xs, ys;
	windowPoints(xs, ys);
	m_reference.clear();
	for (size_t i = 0; i < xs.size(); ++i) m_reference.insertPointFast(xs[i], ys[i], 0);
	m_reference.mark_as_modified();
	return m_reference;
}

const CPointIndex2D& CKeyframePointMap::referenceIndex(const mrpt::poses::CPose2D& robotPose)
{
	updateWindow(robotPose);
	if (!m_indexStale) return m_index;
	m_indexStale = false;
	if (!updateIndexIncrementally()) rebuildIndex();
	return m_index;
}

void CKeyframePointMap::rebuildIndex()
{
	std::vector<float> xs, ys;
	windowPoints(xs, ys);
	m_index.build(std::move(xs), std::move(ys));
	m_indexPointCounts.clear();
	for (size_t id : m_windowIds) m_indexPointCounts.push_back(m_keyframes[id - m_firstId].worldPoints.size());
	m_indexFirstId = m_windowIds.empty() ? 0 : m_windowIds.front();
	m_indexEndId = m_windowIds.empty() ? 0 : m_windowIds.back() + 1;
	m_indexBulkKeyframes = m_windowIds.size();
}

bool CKeyframePointMap::updateIndexIncrementally()
{
	// Only a window of consecutive keyframes that moved forward (no radius,
	// no merging) can be updated in place.
	if (m_options.voxel_size_m > 0 || m_options.radius_m > 0 || m_windowIds.empty() || m_index.size() == 0) return false;
	const size_t first = m_windowIds.front(), end = m_windowIds.back() + 1;
	if (first < m_indexFirstId || end < m_indexEndId || first >= m_indexEndId) return false;
	if (end - m_indexFirstId - m_indexBulkKeyframes > static_cast<size_t>(m_options.index_rebuild_keyframes))
		return false;
	for (; m_indexFirstId < first; ++m_indexFirstId)  // retire keyframes that left the window
	{
		if (m_indexBulkKeyframes == 0) return false;  // a recent keyframe left: rebuild
		m_indexPointCounts.pop_front(), --m_indexBulkKeyframes;
	}
	size_t retired = m_index.bulkSize();
	for (size_t i = 0; i < m_indexBulkKeyframes; ++i) retired -= m_indexPointCounts[i];
	m_index.retireBelow(retired);
	std::vector<float> xs, ys;
	for (; m_indexEndId < end; ++m_indexEndId)
	{
		const auto& points = m_keyframes[m_indexEndId - m_firstId].worldPoints;
		for (const auto& p : points) xs.push_back(static_cast<float>(p.x)), ys.push_back(static_cast<float>(p.y));
		m_indexPointCounts.push_back(points.size());
	}
	if (!xs.empty()) m_index.append(xs, ys);
	return true;
}

void CKeyframePointMap::windowPoints(std::vector<float>& xs, std::vector<float>& ys) const
{
	if (m_options.voxel_size_m > 0) return mergedWindowPoints(xs, ys);
	for (size_t id : m_windowIds)
		for (const auto& p : m_keyframes[id - m_firstId].worldPoints)
			xs.push_back(static_cast<float>(p.x)), ys.push_back(static_cast<float>(p.y));
}

void CKeyframePointMap::mergedWindowPoints(std::vector<float>& xs, std::vector<float>& ys) const
{
	struct TCellSum
	{
		double x = 0, y = 0;
		int count = 0;
	};
	std::unordered_map<int64_t, size_t> cellIndex;
	std::vector<TCellSum> cells;  // in order of first appearance: deterministic output
	const double inv = 1.0 / m_options.voxel_size_m;
	for (size_t id : m_windowIds)
		for (const auto& p : m_keyframes[id - m_firstId].worldPoints)
		{
			const int64_t key = common::cellKey(static_cast<int>(std::floor(p.x * inv)), static_cast<int>(std::floor(p.y * inv)));
			const auto [it, added] = cellIndex.try_emplace(key, cells.size());
			if (added) cells.emplace_back();
			auto& c = cells[it->second];
			c.x += p.x, c.y += p.y, ++c.count;
		}
	for (const auto& c : cells)
		xs.push_back(static_cast<float>(c.x / c.count)), ys.push_back(static_cast<float>(c.y / c.count));
}

}  // namespace hslam::matching
