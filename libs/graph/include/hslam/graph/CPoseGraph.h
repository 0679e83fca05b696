/* hslam graph: the pose graph over keyframes (issue 13, part 1 and 3).
 *
 * Nodes are keyframes (keyframe id, pose, group = the tile that holds them:
 * the thesis's topological layer of tiles, chapter 3). Edges are relative
 * poses with a 3x3 information matrix and a kind: sequential (front-end),
 * weak (across an odometry gap: never rigid) and loop (closures).
 *
 * optimize() runs sparse Levenberg-Marquardt (Konolige et al. 2010) over the
 * active edges, node 0 fixed: by default on Eigen's sparse Cholesky
 * (sparse_pose_solver.h, `solver = sparse`), or MRPT's
 * mrpt::graphslam::optimize_graph_spa_levmarq over a
 * mrpt::graphs::CNetworkOfPoses2DInf (`solver = mrpt`), which is the same
 * model but O(edges x nodes) to set up (docs/loop-closure.md).
 * Robustness against wrong closures: after each solve the loop edge of largest
 * chi2 above `max_loop_chi2` is switched off and the graph is solved again
 * from the poses before the call (edge dropping, the hard form of switchable
 * constraints, Suenderhauf & Protzel 2012); sequential and weak edges are
 * never dropped. The graph is exported in MRPT's .graph text format
 * (g2o-style VERTEX_SE2 / EDGE_SE2 lines, as MRPT writes them), which MRPT's
 * graph-slam app reads. */
#pragma once

#include <mrpt/math/TPose2D.h>

#include <Eigen/Core>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace hslam::graph
{
enum class EEdgeKind : uint8_t
{
	sequential = 0,  //!< consecutive keyframes, from the front-end's match
	weak = 1,  //!< consecutive keyframes across an odometry gap / lost tracking
	loop = 2  //!< a verified loop closure
};
/** "sequential", "weak", "loop". */
const char* edgeKindName(EEdgeKind kind);

struct TGraphNode
{
	int64_t keyframe_id = -1;
	mrpt::math::TPose2D pose;  //!< world frame (optimised after optimize())
	int group = -1;  //!< tile index (-1 = none)
};

struct TGraphEdge
{
	size_t from = 0, to = 0;  //!< node indices
	mrpt::math::TPose2D relative;  //!< pose of `to` in the frame of `from`
	Eigen::Matrix3d information = Eigen::Matrix3d::Identity();  //!< inverse covariance (x, y, yaw)
	EEdgeKind kind = EEdgeKind::sequential;
	bool active = true;  //!< false once dropped by the robust step
};

struct TPoseGraphOptions
{
	int max_iterations = 100;  //!< Levenberg-Marquardt iterations per solve
	double max_loop_chi2 = 16.27;  //!< loop edges above (3-dof chi2, 99.9 %) after a solve are dropped
	int max_drop_rounds = 5;  //!< at most this many loop edges dropped per optimize()
	std::string solver = "sparse";  //!< "sparse" (Eigen, sparse_pose_solver.h) or "mrpt" (optimize_graph_spa_levmarq)

	template <class V>
	void visit(V& v)
	{
		v.choice("solver", solver, {"sparse", "mrpt"});
		v.integer("max_iterations", max_iterations, 1, 10000);
		v.real("max_loop_chi2", max_loop_chi2, 0.1, 1e9);
		v.integer("max_drop_rounds", max_drop_rounds, 0, 100);
	}
};

struct TOptimizationReport
{
	size_t iterations = 0;  //!< summed over the solves
	size_t solves = 0;
	double initial_chi2 = 0, final_chi2 = 0;  //!< sum over active edges
	double time_ms = 0;
	std::vector<size_t> dropped_edges;  //!< loop edges switched off by this call
};

class CPoseGraph
{
   public:
	using TOptions = TPoseGraphOptions;

	explicit CPoseGraph(const TOptions& options = TOptions()) : m_options(options) {}

	/** Adds a node; returns its index (0, 1, ...). */
	size_t addNode(int64_t keyframeId, const mrpt::math::TPose2D& pose, int group = -1);
	/** Adds an edge between existing nodes; returns its index. Throws
	 * std::invalid_argument for unknown nodes or a non-positive-definite
	 * information matrix. */
	size_t addEdge(const TGraphEdge& edge);
	void setEdgeActive(size_t edge, bool active) { m_edges.at(edge).active = active; }
	void setNodePose(size_t node, const mrpt::math::TPose2D& pose) { m_nodes.at(node).pose = pose; }

	const std::vector<TGraphNode>& nodes() const { return m_nodes; }
	const std::vector<TGraphEdge>& edges() const { return m_edges; }
	size_t nodeCount() const { return m_nodes.size(); }

	/** e^T Omega e of an edge at the current node poses. */
	double edgeChi2(size_t edge) const;
	double totalChi2() const;

	/** Optimises all nodes but node 0, dropping inconsistent loop edges. */
	TOptimizationReport optimize();

	/** MRPT .graph text (active edges only; node ids = node indices). */
	void writeGraphText(std::ostream& out) const;
	/** Same into a file; throws std::runtime_error naming the path on failure. */
	void saveGraphFile(const std::string& path) const;

	const TOptions& options() const { return m_options; }

   private:
	/** One MRPT solve of the active edges from the current poses. */
	size_t solveOnce();

	TOptions m_options;
	std::vector<TGraphNode> m_nodes;
	std::vector<TGraphEdge> m_edges;
};

/** Relative pose of b in the frame of a (a^-1 (+) b). */
mrpt::math::TPose2D relativePose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b);
/** a (+) d. */
mrpt::math::TPose2D composePose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& d);

}  // namespace hslam::graph
