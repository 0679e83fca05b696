/* hslam: keyframe store (see CKeyframeStore.h). */
#include <hslam/matching/CKeyframeStore.h>

#include "point_scatter.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace hslam::matching
{
namespace
{
/** Normal of the points [first, last] (robot frame) if they lie on a line. */
bool fitNormal(const common::TScanPoints& pts, size_t first, size_t last, Eigen::Vector2d& normal)
{
	if (last < first + 2) return false;
	const auto eig = detail::scatterOf(last - first + 1, [&](size_t j)
									   { return Eigen::Vector2d(pts.xy[first + j].x, pts.xy[first + j].y); });
	if (eig.eigenvalues()[1] <= 0 || eig.eigenvalues()[0] > 0.25 * eig.eigenvalues()[1]) return false;
	normal = eig.eigenvectors().col(0);
	return true;
}

double distance2(const common::TScanPoints& pts, size_t a, size_t b)
{
	const double dx = pts.xy[a].x - pts.xy[b].x, dy = pts.xy[a].y - pts.xy[b].y;
	return dx * dx + dy * dy;
}
}  // namespace

TOrientedPoints pointsWithNormals(const common::TScanPoints& pts, const CKeyframeStore::TOptions& o,
								  const std::vector<bool>* excludedBeams)
{
	TOrientedPoints out;
	const double radius2 = o.normal_radius_m * o.normal_radius_m, spacing2 = o.min_point_spacing_m * o.min_point_spacing_m;
	Eigen::Vector2d lastKept(1e300, 1e300);
	for (size_t i = 0; i < pts.size(); ++i)
	{
		if (pts.range_m[i] > o.max_range_m || (excludedBeams && (*excludedBeams)[pts.beam[i]])) continue;
		const Eigen::Vector2d p(pts.xy[i].x, pts.xy[i].y);
		if ((p - lastKept).squaredNorm() < spacing2) continue;
		size_t first = i, last = i;  // neighbours in beam order, consecutive beams only
		while (first > 0 && pts.beam[first - 1] + 1 == pts.beam[first] && distance2(pts, first - 1, i) <= radius2) --first;
		while (last + 1 < pts.size() && pts.beam[last + 1] == pts.beam[last] + 1 && distance2(pts, last + 1, i) <= radius2)
			++last;
		Eigen::Vector2d n;
		if (!fitNormal(pts, first, last, n)) continue;
		if (n.dot(p) > 0) n = -n;  // towards the sensor (consistent sign; unused by point-to-line)
		out.points.push_back(p), out.normals.push_back(n);
		lastKept = p;
	}
	return out;
}

bool CKeyframeStore::wantsKeyframe(const mrpt::poses::CPose2D& pose) const
{
	if (m_keyframes.empty()) return true;
	const auto& last = m_keyframes.back().pose;
	return pose.distanceTo(last) >= m_options.insertion_distance_m ||
		   std::abs(mrpt::math::wrapToPi(pose.phi() - last.phi())) >= m_options.insertion_angle_rad;
}

size_t CKeyframeStore::add(const common::TScanPoints& points, const mrpt::poses::CPose2D& pose,
						   const Eigen::Matrix3d& covariance, double t_s)
{
	TKeyframe k;
	k.id = m_keyframes.size();
	k.t_s = t_s;
	k.pose = pose;
	k.covariance = covariance;
	k.scan = pointsWithNormals(points, m_options);
	m_keyframes.push_back(std::move(k));
	return m_keyframes.back().id;
}

void CKeyframeStore::setPose(size_t id, const mrpt::poses::CPose2D& pose)
{
	m_keyframes.at(id).pose = pose;
	++m_revision;
}

std::vector<size_t> CKeyframeStore::window(const mrpt::poses::CPose2D& robotPose) const
{
	const size_t n = m_keyframes.size(), recent = std::min<size_t>(n, static_cast<size_t>(m_options.window_keyframes));
	std::vector<size_t> ids;
	if (m_options.window_radius_m > 0)
	{
		std::vector<std::pair<double, size_t>> near;  // older keyframes near the robot, nearest first
		for (size_t i = 0; i + recent < n; ++i)
		{
			const double d = m_keyframes[i].pose.distanceTo(robotPose);
			if (d <= m_options.window_radius_m) near.emplace_back(d, i);
		}
		std::sort(near.begin(), near.end());
		const size_t room = static_cast<size_t>(std::max(0, m_options.window_max_keyframes - static_cast<int>(recent)));
		for (size_t k = 0; k < near.size() && k < room; ++k) ids.push_back(near[k].second);
	}
	for (size_t i = n - recent; i < n; ++i) ids.push_back(i);
	std::sort(ids.begin(), ids.end());
	return ids;
}

}  // namespace hslam::matching
