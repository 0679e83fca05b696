/* hslam graph: a sparse Levenberg-Marquardt solver for 2D pose graphs on
 * Eigen's sparse Cholesky (SimplicialLDLT, AMD ordering).
 *
 * Why not only MRPT's optimize_graph_spa_levmarq: its set-up maps every edge
 * to its free-node index with a linear search over a std::set
 * (mrpt::containers::find_in_vector), O(edges x nodes) per solve: 2.1 s for
 * one closure on a 10 000-keyframe graph, 72 % of it in that search
 * (hslam-bench graph, docs/loop-closure.md). This solver has the same model
 * (Konolige et al. 2010, "Sparse Pose Adjustment": error of edge i->j is
 * t2v(Z^-1 (X_i^-1 X_j)), weighted by its information matrix; node 0 fixed)
 * with O(edges) set-up and a fill-reducing ordering. */
#pragma once

#include <hslam/graph/CPoseGraph.h>

#include <vector>

namespace hslam::graph
{
struct TSparseSolverOptions
{
	int max_iterations = 100;
	double initial_lambda = 1e-6;  //!< LM damping, relative to the diagonal of H
	double min_relative_chi2_decrease = 1e-9;  //!< converged below this
	double min_step = 1e-9;  //!< converged when every update component is below this (m, rad)
};

/** Solves for every node pose but node 0 (held fixed), from the poses in
 * `nodes`, over the active edges; writes the solution into `nodes` and
 * returns the iterations run. */
size_t solvePoseGraphSparse(std::vector<TGraphNode>& nodes, const std::vector<TGraphEdge>& edges,
							const TSparseSolverOptions& options);

}  // namespace hslam::graph
