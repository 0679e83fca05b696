#include <hslam/graph/CLoopClosureDetector.h>
#include <hslam/common/cell_key.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "loop_closure_candidate.h"

namespace hslam::graph
{
namespace
{
/** Points of several keyframes in the anchor frame, one per cell of `cell_m`. */
TPointCloud2D submapPoints(const std::vector<std::pair<size_t, TPointCloud2D>>& keyframes, const CPoseGraph& graph,
						   size_t anchor, double cell_m)
{
	TPointCloud2D out;
	std::unordered_set<int64_t> used;
	for (const auto& [node, points] : keyframes)
	{
		const auto rel = mrpt::poses::CPose2D(relativePose(graph.nodes()[anchor].pose, graph.nodes()[node].pose));
		for (const auto& p : points)
		{
			double x, y;
			rel.composePoint(p.x, p.y, x, y);
			const int64_t key = common::cellKey(static_cast<int>(std::floor(x / cell_m)), static_cast<int>(std::floor(y / cell_m)));
			if (used.insert(key).second) out.push_back({static_cast<float>(x), static_cast<float>(y)});
		}
	}
	return out;
}
}  // namespace

Eigen::Matrix3d relativeChainCovariance(const mrpt::math::TPose2D& a, const Eigen::Matrix3d& covA,
										const mrpt::math::TPose2D& i, const Eigen::Matrix3d& covI, double floor)
{
	Eigen::Matrix3d J = Eigen::Matrix3d::Identity();
	J(0, 2) = -(i.y - a.y), J(1, 2) = i.x - a.x;
	const Eigen::Matrix3d diff = covI - J * covA * J.transpose();
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(0.5 * (diff + diff.transpose()));
	const Eigen::Vector3d ev = es.eigenvalues().cwiseMax(floor);
	return es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
}

CLoopClosureDetector::CLoopClosureDetector(const TOptions& options) : m_options(options) {}
CLoopClosureDetector::~CLoopClosureDetector() = default;

void CLoopClosureDetector::addKeyframe(size_t node, const TPointCloud2D& points, const CPoseGraph& graph)
{
	m_queryNode = node;
	m_queryPoints = points;
	m_pending.emplace_back(node, points);
	if (static_cast<int>(m_pending.size()) >= m_options.submap_keyframes) closeSubmap(graph);
}

void CLoopClosureDetector::closeSubmap(const CPoseGraph& graph)
{
	TSubmap s;
	s.first_node = m_pending.front().first;
	s.last_node = m_pending.back().first;
	s.anchor_node = m_pending[m_pending.size() / 2].first;
	s.points = submapPoints(m_pending, graph, s.anchor_node, m_options.matcher.resolution_m);
	m_submaps.push_back(std::move(s));
	m_pending.clear();
}

const CLoopClosureDetector::TSubmapField& CLoopClosureDetector::fieldOf(size_t submap)
{
	for (auto it = m_fieldCache.begin(); it != m_fieldCache.end(); ++it)
		if (it->first == submap)
		{
			m_fieldCache.splice(m_fieldCache.begin(), m_fieldCache, it);
			return *m_fieldCache.front().second;
		}
	auto field = std::make_unique<TSubmapField>(TSubmapField{CCorrelativeScanMatcher(m_options.matcher), {}});
	const auto& points = m_submaps[submap].points;
	field->matcher.setReference(points);
	field->points.reserve(points.size());
	for (const auto& p : points) field->points.insertPointFast(p.x, p.y, 0);
	m_fieldCache.emplace_front(submap, std::move(field));
	while (static_cast<int>(m_fieldCache.size()) > m_options.max_cached_fields) m_fieldCache.pop_back();
	return *m_fieldCache.front().second;
}

std::vector<CLoopClosureDetector::TCandidate> CLoopClosureDetector::candidates(
	size_t node, const CPoseGraph& graph, const std::vector<Eigen::Matrix3d>& chainCovariance) const
{
	const auto& query = graph.nodes()[node].pose;
	std::vector<TCandidate> out;
	for (size_t s = 0; s < m_submaps.size(); ++s)
	{
		const auto& sm = m_submaps[s];
		if (sm.last_node + static_cast<size_t>(m_options.min_separation_keyframes) > node) continue;
		const auto& anchor = graph.nodes()[sm.anchor_node].pose;
		TCandidate c;
		c.submap = s;
		c.relativeCovariance =
			relativeChainCovariance(anchor, chainCovariance[sm.anchor_node], query, chainCovariance[node]);
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> xy(c.relativeCovariance.topLeftCorner<2, 2>());
		c.window.xy_m = std::clamp(m_options.window_sigmas * std::sqrt(xy.eigenvalues().maxCoeff()),
								   m_options.min_window_xy_m, m_options.max_window_xy_m);
		c.window.yaw_rad = std::clamp(m_options.window_sigmas * std::sqrt(c.relativeCovariance(2, 2)),
									  m_options.min_window_yaw_rad, m_options.max_window_yaw_rad);
		c.distance_m = std::hypot(query.x - anchor.x, query.y - anchor.y);
		if (c.distance_m > m_options.overlap_distance_m + c.window.xy_m) continue;
		out.push_back(c);
	}
	std::sort(out.begin(), out.end(), [](const TCandidate& a, const TCandidate& b) { return a.distance_m < b.distance_m; });
	if (static_cast<int>(out.size()) > m_options.max_candidates) out.resize(static_cast<size_t>(m_options.max_candidates));
	return out;
}

std::vector<TLoopClosure> CLoopClosureDetector::detect(size_t node, const CPoseGraph& graph,
													   const std::vector<Eigen::Matrix3d>& chainCovariance)
{
	std::vector<TLoopClosure> out;
	if (node != m_queryNode || node % static_cast<size_t>(m_options.detect_every_n_keyframes) != 0) return out;
	for (const auto& c : candidates(node, graph, chainCovariance)) out.push_back(verify(c, node, graph));
	return out;
}

}  // namespace hslam::graph
