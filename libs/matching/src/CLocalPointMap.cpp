/* hslam: local map of scan-to-map matching (see CLocalPointMap.h). */
#include <hslam/matching/CLocalPointMap.h>

namespace hslam::matching
{
CLocalPointMap::CLocalPointMap() = default;
CLocalPointMap::~CLocalPointMap() = default;

void CLocalPointMap::update(const CKeyframeStore& store, const std::vector<size_t>& ids)
{
	if (ids == m_ids && store.revision() == m_revision && m_tree) return;
	m_ids = ids;
	m_revision = store.revision();
	m_points.clear(), m_normals.clear();
	for (size_t id : ids)
	{
		const TKeyframe& k = store.keyframe(id);
		const double c = std::cos(k.pose.phi()), s = std::sin(k.pose.phi());
		Eigen::Matrix2d R;
		R << c, -s, s, c;
		const Eigen::Vector2d t(k.pose.x(), k.pose.y());
		for (size_t i = 0; i < k.scan.size(); ++i)
		{
			m_points.push_back(R * k.scan.points[i] + t);
			m_normals.push_back(R * k.scan.normals[i]);
		}
	}
	m_tree = std::make_unique<TTree>(2, *this, nanoflann::KDTreeSingleIndexAdaptorParams(10));
	m_tree->buildIndex();
}

long CLocalPointMap::nearest(const Eigen::Vector2d& q, double max_distance_m) const
{
	if (!m_tree || m_points.empty()) return -1;
	uint32_t index = 0;
	double distance2 = 0;
	nanoflann::KNNResultSet<double, uint32_t> result(1);
	result.init(&index, &distance2);
	m_tree->findNeighbors(result, q.data(), nanoflann::SearchParams());
	if (result.size() == 0 || distance2 > max_distance_m * max_distance_m) return -1;
	return static_cast<long>(index);
}

}  // namespace hslam::matching
