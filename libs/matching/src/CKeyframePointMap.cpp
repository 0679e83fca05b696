#include <hslam/fusion/se2.h>
#include <hslam/matching/CKeyframePointMap.h>

#include <cmath>

namespace hslam::matching
{
bool CKeyframePointMap::wantsKeyframe(const mrpt::poses::CPose2D& pose) const
{
	if (m_keyframes.empty()) return true;
	const auto& last = m_keyframes.back().pose;
	return pose.distanceTo(last) >= m_options.insertion_distance_m ||
		   std::abs(fusion::wrapToPi(pose.phi() - last.phi())) >= m_options.insertion_angle_rad;
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

const mrpt::maps::CSimplePointsMap& CKeyframePointMap::reference(const mrpt::poses::CPose2D& robotPose)
{
	std::vector<size_t> window;
	for (size_t i = 0; i < m_keyframes.size(); ++i)
		if (m_options.radius_m <= 0 || m_keyframes[i].pose.distanceTo(robotPose) <= m_options.radius_m)
			window.push_back(m_firstId + i);
	if (window == m_windowIds && m_reference.size() > 0) return m_reference;
	m_windowIds = window;
	m_reference.clear();
	for (size_t id : window)
		for (const auto& p : m_keyframes[id - m_firstId].worldPoints) m_reference.insertPointFast(p.x, p.y, 0);
	m_reference.mark_as_modified();
	return m_reference;
}

}  // namespace hslam::matching
