#include <hslam/graph/CGraphBackend.h>
#include <hslam/graph/dijkstra_projection.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <memory>

namespace hslam::graph
{
namespace
{
double msSince(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

CGraphBackend::CGraphBackend(const TGraphBackendOptions& options, const TLoopClosureOptions& loopOptions)
	: m_options(options), m_graph(options.graph), m_detector(loopOptions)
{
}

size_t CGraphBackend::addNodeAndSequentialEdge(const TKeyframe& kf)
{
	if (m_graph.nodeCount() == 0)
	{
		m_frontendPoses.push_back(kf.pose);
		return m_graph.addNode(kf.id, kf.pose, kf.group);
	}
	const size_t prev = m_graph.nodeCount() - 1;
	const auto rel = relativePose(m_frontendPoses.back(), kf.pose);
	// The floor is added, not taken as a maximum of the diagonal: a covariance
	// that is singular along a rotated direction keeps its diagonal above any
	// floor and would give a singular information matrix.
	Eigen::Matrix3d cov = 0.5 * (kf.relative_covariance + kf.relative_covariance.transpose());
	cov += Eigen::Vector3d(m_options.min_sequential_xy_std_m * m_options.min_sequential_xy_std_m,
						   m_options.min_sequential_xy_std_m * m_options.min_sequential_xy_std_m,
						   m_options.min_sequential_yaw_std_rad * m_options.min_sequential_yaw_std_rad)
			   .asDiagonal();
	if (kf.after_gap)
		cov += Eigen::Vector3d(m_options.weak_xy_std_m * m_options.weak_xy_std_m,
							   m_options.weak_xy_std_m * m_options.weak_xy_std_m,
							   m_options.weak_yaw_std_rad * m_options.weak_yaw_std_rad)
				   .asDiagonal();
	const mrpt::math::TPose2D prevPose = m_graph.nodes()[prev].pose;  // a copy: addNode may reallocate the nodes
	const size_t node = m_graph.addNode(kf.id, composePose(prevPose, rel), kf.group);
	TGraphEdge e;
	e.from = prev, e.to = node, e.relative = rel, e.information = cov.inverse();
	e.kind = kf.after_gap ? EEdgeKind::weak : EEdgeKind::sequential;
	m_graph.addEdge(e);
	m_frontendPoses.push_back(kf.pose);
	return node;
}

TKeyframeResult CGraphBackend::addKeyframe(const TKeyframe& kf)
{
	const auto t0 = std::chrono::steady_clock::now();
	TKeyframeResult result;
	result.node = addNodeAndSequentialEdge(kf);
	m_detector.addKeyframe(result.node, kf.points, m_graph);
	std::vector<size_t> released;  //!< closures of earlier keyframes confirmed now
	const size_t firstNewEdge = m_graph.edges().size();
	if (m_options.detect_loops)
	{
		const auto td = std::chrono::steady_clock::now();
		result.closures = m_detector.detect(result.node, m_graph, relativeCovariances(result.node));
		m_timing.detect_ms += msSince(td);
		m_timing.candidates_tested += result.closures.size();
		released = confirmClosures(result.closures);
		const size_t firstNew = m_closures.size();
		addClosures(result.closures);
		for (const size_t k : released) addLoopEdge(m_closures[k]);
		rememberVerified(result.node, firstNew);
	}
	const size_t newLoopEdges = m_graph.edges().size() - firstNewEdge;
	m_pendingLoopEdges += newLoopEdges;
	if (newLoopEdges > 0 && closuresNeedOptimization(firstNewEdge))
		result.optimization = optimize(), result.optimized = true;
	else
		m_timing.closures_deferred += newLoopEdges;
	for (auto& c : result.closures)  // report the status after the optimiser
		for (const auto& stored : m_closures)
			if (c.edge >= 0 && stored.edge == c.edge) c.accepted = stored.accepted, c.reason = stored.reason;
	if (m_options.detect_loops) m_detector.keepTracks(result.node, result.closures);
	result.time_ms = msSince(t0);
	++m_timing.keyframes;
	m_timing.total_ms += result.time_ms;
	m_timing.max_keyframe_ms = std::max(m_timing.max_keyframe_ms, result.time_ms);
	return result;
}

bool CGraphBackend::closuresNeedOptimization(size_t firstNewEdge) const
{
	for (size_t e = firstNewEdge; e < m_graph.edges().size(); ++e)
		if (m_graph.edges()[e].kind == EEdgeKind::loop && m_graph.edgeChi2(e) > m_options.optimize_min_closure_chi2)
			return true;
	return false;
}

TOptimizationReport CGraphBackend::optimize()
{
	TOptimizationReport report = m_graph.optimize();
	m_pendingLoopEdges = 0;
	markDroppedClosures(report);
	++m_timing.optimizations;
	m_timing.optimize_ms += report.time_ms;
	m_timing.max_optimize_ms = std::max(m_timing.max_optimize_ms, report.time_ms);
	return report;
}

std::optional<TOptimizationReport> CGraphBackend::flushPendingClosures()
{
	if (m_pendingLoopEdges == 0) return std::nullopt;
	const auto report = optimize();
	m_timing.total_ms += report.time_ms;
	return report;
}

CLoopClosureDetector::TRelativeCovariance CGraphBackend::relativeCovariances(size_t query) const
{
	// computed on the first question only: most keyframes are not queried
	auto fromQuery = std::make_shared<std::vector<std::optional<Eigen::Matrix3d>>>();
	return [this, fromQuery, query](size_t anchor) -> std::optional<Eigen::Matrix3d> {
		if (fromQuery->empty()) *fromQuery = dijkstraProjection(m_graph, query);
		if (!(*fromQuery)[anchor]) return std::nullopt;
		return swapFixedEnd(m_graph.nodes()[query].pose, m_graph.nodes()[anchor].pose, *(*fromQuery)[anchor]);
	};
}

void CGraphBackend::addClosures(std::vector<TLoopClosure>& tested)
{
	for (auto& c : tested)
	{
		if (c.accepted) addLoopEdge(c);
		m_closures.push_back(c);
	}
}

void CGraphBackend::addLoopEdge(TLoopClosure& c)
{
	c.accepted = true;
	c.reason = "accepted";
	TGraphEdge e;
	e.from = c.anchor_node, e.to = c.query_node, e.relative = c.relative, e.kind = EEdgeKind::loop;
	e.information = (m_options.loop_edge_covariance_factor * c.covariance).inverse();
	c.edge = static_cast<long>(m_graph.addEdge(e));
	++m_timing.closures_accepted;
}

void CGraphBackend::markDroppedClosures(const TOptimizationReport& report)
{
	for (size_t edge : report.dropped_edges)
		for (auto& c : m_closures)
			if (c.edge == static_cast<long>(edge) && c.accepted)
			{
				c.accepted = false;
				c.reason = "dropped by optimiser";
				if (m_timing.closures_accepted > 0) --m_timing.closures_accepted;
			}
}

std::vector<mrpt::math::TPose2D> CGraphBackend::optimizedPoses() const
{
	std::vector<mrpt::math::TPose2D> out;
	for (const auto& n : m_graph.nodes()) out.push_back(n.pose);
	return out;
}

mrpt::math::TPose2D CGraphBackend::correction() const
{
	if (m_frontendPoses.empty()) return {0, 0, 0};
	// T = optimised (+) frontend^-1
	return composePose(m_graph.nodes().back().pose, relativePose(m_frontendPoses.back(), {0, 0, 0}));
}

}  // namespace hslam::graph
