#include <hslam/graph/dijkstra_projection.h>

#include <Eigen/Dense>
#include <functional>
#include <queue>

namespace hslam::graph
{
namespace
{
/** blockdiag(R(yaw), 1): a covariance in a frame at `yaw` -> world frame. */
Eigen::Matrix3d frameRotation(double yaw)
{
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	R(0, 0) = std::cos(yaw), R(0, 1) = -std::sin(yaw);
	R(1, 0) = std::sin(yaw), R(1, 1) = std::cos(yaw);
	return R;
}

/** Jacobian of the inverse of the relative pose r = (x, y, yaw). */
Eigen::Matrix3d inverseJacobian(const mrpt::math::TPose2D& r)
{
	const double c = std::cos(r.phi), s = std::sin(r.phi);
	Eigen::Matrix3d J;
	J << -c, -s, r.x * s - r.y * c, s, -c, r.x * c + r.y * s, 0, 0, -1;
	return J;
}

struct TStep
{
	size_t edge;
	bool forward;  //!< traversed from -> to
};

/** Covariance of an edge's far end given its near end, world frame. */
Eigen::Matrix3d stepCovariance(const CPoseGraph& graph, const TStep& step)
{
	const auto& e = graph.edges()[step.edge];
	const Eigen::Matrix3d C = e.information.inverse();
	if (step.forward) return frameRotation(graph.nodes()[e.from].pose.phi) * C * frameRotation(graph.nodes()[e.from].pose.phi).transpose();
	const Eigen::Matrix3d J = inverseJacobian(e.relative);
	const Eigen::Matrix3d R = frameRotation(graph.nodes()[e.to].pose.phi);
	return R * J * C * J.transpose() * R.transpose();
}

/** Covariance of `to` given `from` fixed: `from`'s uncertainty moved by the
 * lever arm of its yaw, plus the step's own. */
Eigen::Matrix3d propagate(const Eigen::Matrix3d& from, const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b,
						  const Eigen::Matrix3d& step)
{
	Eigen::Matrix3d Ja = Eigen::Matrix3d::Identity();
	Ja(0, 2) = -(b.y - a.y), Ja(1, 2) = b.x - a.x;
	return Ja * from * Ja.transpose() + step;
}

std::vector<std::vector<TStep>> adjacency(const CPoseGraph& graph)
{
	std::vector<std::vector<TStep>> adj(graph.nodeCount());
	for (size_t k = 0; k < graph.edges().size(); ++k)
	{
		const auto& e = graph.edges()[k];
		if (!e.active) continue;
		adj[e.from].push_back({k, true});
		adj[e.to].push_back({k, false});
	}
	return adj;
}
}  // namespace

std::vector<std::optional<Eigen::Matrix3d>> dijkstraProjection(const CPoseGraph& graph, size_t source)
{
	std::vector<std::optional<Eigen::Matrix3d>> cov(graph.nodeCount());
	if (source >= graph.nodeCount()) return cov;
	const auto adj = adjacency(graph);
	std::vector<bool> done(graph.nodeCount(), false);
	using TItem = std::pair<double, size_t>;  // (trace, node)
	std::priority_queue<TItem, std::vector<TItem>, std::greater<TItem>> open;
	cov[source] = Eigen::Matrix3d::Zero();
	open.push({0.0, source});
	while (!open.empty())
	{
		const size_t u = open.top().second;
		open.pop();
		if (done[u]) continue;
		done[u] = true;
		for (const auto& step : adj[u])
		{
			const auto& e = graph.edges()[step.edge];
			const size_t v = step.forward ? e.to : e.from;
			if (done[v]) continue;
			const Eigen::Matrix3d c =
				propagate(*cov[u], graph.nodes()[u].pose, graph.nodes()[v].pose, stepCovariance(graph, step));
			if (cov[v] && cov[v]->trace() <= c.trace()) continue;
			cov[v] = c;
			open.push({c.trace(), v});
		}
	}
	return cov;
}

Eigen::Matrix3d swapFixedEnd(const mrpt::math::TPose2D& source, const mrpt::math::TPose2D& node,
							 const Eigen::Matrix3d& nodeGivenSource)
{
	// node in the source's frame, its covariance there, then the inverse pose
	const double c = std::cos(source.phi), s = std::sin(source.phi);
	const double dx = node.x - source.x, dy = node.y - source.y;
	const mrpt::math::TPose2D r{c * dx + s * dy, -s * dx + c * dy, node.phi - source.phi};
	const Eigen::Matrix3d Rs = frameRotation(source.phi);
	const Eigen::Matrix3d inSource = Rs.transpose() * nodeGivenSource * Rs;
	const Eigen::Matrix3d J = inverseJacobian(r);
	const Eigen::Matrix3d Rn = frameRotation(node.phi);
	return Rn * J * inSource * J.transpose() * Rn.transpose();
}

}  // namespace hslam::graph
