#include <hslam/graph/CPoseGraph.h>
#include <hslam/graph/sparse_pose_solver.h>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/levmarq.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Cholesky>
#include <chrono>
#include <fstream>
#include <stdexcept>

namespace hslam::graph
{
const char* edgeKindName(EEdgeKind kind)
{
	switch (kind)
	{
		case EEdgeKind::sequential: return "sequential";
		case EEdgeKind::weak: return "weak";
		case EEdgeKind::loop: return "loop";
	}
	return "?";
}

mrpt::math::TPose2D relativePose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	return (mrpt::poses::CPose2D(b) - mrpt::poses::CPose2D(a)).asTPose();
}

mrpt::math::TPose2D composePose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& d)
{
	return (mrpt::poses::CPose2D(a) + mrpt::poses::CPose2D(d)).asTPose();
}

namespace
{
mrpt::graphs::CNetworkOfPoses2DInf toMrpt(const std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges)
{
	mrpt::graphs::CNetworkOfPoses2DInf g;
	for (size_t i = 0; i < nodes.size(); ++i) g.nodes[i] = mrpt::poses::CPose2D(nodes[i].pose);
	g.root = 0;
	for (const auto& e : edges)
	{
		if (!e.active) continue;
		mrpt::poses::CPosePDFGaussianInf pdf;
		pdf.mean = mrpt::poses::CPose2D(e.relative);
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 3; ++c) pdf.cov_inv(r, c) = e.information(r, c);
		g.insertEdge(e.from, e.to, pdf);
	}
	return g;
}
}  // namespace

size_t CPoseGraph::addNode(int64_t keyframeId, const mrpt::math::TPose2D& pose, int group)
{
	m_nodes.push_back({keyframeId, pose, group});
	return m_nodes.size() - 1;
}

size_t CPoseGraph::addEdge(const TGraphEdge& edge)
{
	if (edge.from >= m_nodes.size() || edge.to >= m_nodes.size() || edge.from == edge.to)
		throw std::invalid_argument("CPoseGraph::addEdge: edge " + std::to_string(edge.from) + " -> " +
									std::to_string(edge.to) + " does not join two existing nodes");
	const Eigen::Matrix3d sym = 0.5 * (edge.information + edge.information.transpose());
	if (!sym.allFinite() || Eigen::LLT<Eigen::Matrix3d>(sym).info() != Eigen::Success)
		throw std::invalid_argument("CPoseGraph::addEdge: information matrix of edge " + std::to_string(edge.from) +
									" -> " + std::to_string(edge.to) + " is not positive definite");
	m_edges.push_back(edge);
	m_edges.back().information = sym;
	return m_edges.size() - 1;
}

double CPoseGraph::edgeChi2(size_t edge) const
{
	const auto& e = m_edges.at(edge);
	const auto predicted = relativePose(m_nodes[e.from].pose, m_nodes[e.to].pose);
	const auto err = relativePose(e.relative, predicted);
	const Eigen::Vector3d v(err.x, err.y, mrpt::math::wrapToPi(err.phi));
	return v.dot(e.information * v);
}

double CPoseGraph::totalChi2() const
{
	double sum = 0;
	for (size_t i = 0; i < m_edges.size(); ++i)
		if (m_edges[i].active) sum += edgeChi2(i);
	return sum;
}

size_t CPoseGraph::solveOnce()
{
	if (m_options.solver == "sparse")
	{
		TSparseSolverOptions o;
		o.max_iterations = m_options.max_iterations;
		return solvePoseGraphSparse(m_nodes, m_edges, o);
	}
	auto g = toMrpt(m_nodes, m_edges);
	mrpt::graphslam::TResultInfoSpaLevMarq info{};
	mrpt::containers::yaml params;
	params["max_iterations"] = static_cast<uint64_t>(m_options.max_iterations);
	mrpt::graphslam::optimize_graph_spa_levmarq(g, info, nullptr, params);
	for (const auto& [id, pose] : g.nodes) m_nodes[id].pose = pose.asTPose();
	return info.num_iters;
}

TOptimizationReport CPoseGraph::optimize()
{
	TOptimizationReport report;
	const auto t0 = std::chrono::steady_clock::now();
	report.initial_chi2 = totalChi2();
	if (m_nodes.size() < 2) return report;
	std::vector<mrpt::math::TPose2D> start;
	for (const auto& n : m_nodes) start.push_back(n.pose);
	for (int round = 0;; ++round)
	{
		report.iterations += solveOnce();
		++report.solves;
		size_t worst = m_edges.size();
		double worstChi2 = m_options.max_loop_chi2;
		for (size_t i = 0; i < m_edges.size(); ++i)
			if (m_edges[i].active && m_edges[i].kind == EEdgeKind::loop && edgeChi2(i) > worstChi2)
				worst = i, worstChi2 = edgeChi2(i);
		if (worst == m_edges.size() || round >= m_options.max_drop_rounds) break;
		m_edges[worst].active = false;
		report.dropped_edges.push_back(worst);
		for (size_t i = 0; i < m_nodes.size(); ++i) m_nodes[i].pose = start[i];
	}
	report.final_chi2 = totalChi2();
	report.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	return report;
}

void CPoseGraph::writeGraphText(std::ostream& out) const { toMrpt(m_nodes, m_edges).writeAsText(out); }

void CPoseGraph::saveGraphFile(const std::string& path) const
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error("CPoseGraph: cannot write graph file '" + path + "'");
	writeGraphText(f);
	if (!f) throw std::runtime_error("CPoseGraph: error while writing graph file '" + path + "'");
}

}  // namespace hslam::graph
