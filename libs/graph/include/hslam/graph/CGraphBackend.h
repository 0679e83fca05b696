/* hslam graph: the back-end the mapping pipeline calls once per keyframe
 * (issue 13, parts 1-3).
 *
 * addKeyframe() adds a node at the previous node's optimised pose composed
 * with the front-end's motion since the previous keyframe, and a sequential
 * edge whose information is the inverse of the front-end matcher's covariance
 * (floored); across an odometry gap the edge is weak (a large covariance is
 * added: never rigid). Then loop closures are searched and verified
 * (CLoopClosureDetector); the graph is optimised only when an accepted
 * closure disagrees with the current poses (its edge's chi2 above
 * optimize_min_closure_chi2); closures that agree wait for the next
 * optimisation or for flushPendingClosures() at the end of the run.
 * Per-keyframe cost stays bounded: a linear scan over submap anchors (no
 * matching), at most max_candidates matches, and optimisation only on
 * closures.
 *
 * The relative uncertainty of the current keyframe with respect to each
 * candidate anchor, which sizes the search window and gates consistency,
 * comes from the Dijkstra projection over the whole graph, loop edges
 * included (dijkstra_projection.h), computed once per queried keyframe. */
#pragma once

#include <hslam/graph/CLoopClosureDetector.h>
#include <hslam/graph/CPoseGraph.h>

#include <optional>
#include <vector>

namespace hslam::graph
{
struct TGraphBackendOptions
{
	TPoseGraphOptions graph;  //!< optimiser keys, same INI section
	double min_sequential_xy_std_m = 0.01;  //!< floor of the front-end's translation sigma
	double min_sequential_yaw_std_rad = mrpt::DEG2RAD(0.25);  //!< floor of its rotation sigma
	double weak_xy_std_m = 1.0;  //!< added to an edge across an odometry gap
	double weak_yaw_std_rad = mrpt::DEG2RAD(30.0);
	/** A loop edge's covariance is the closure's score-surface covariance
	 * times this: that covariance counts every query point as independent,
	 * neighbouring beams are not (as [icp] covariance_correlation_factor). */
	double loop_edge_covariance_factor = 10.0;
	bool detect_loops = true;  //!< false: the graph only records the front-end's chain
	/** Accepted closures whose loop edges all have at most this chi2 at the
	 * current poses agree with the estimate: they are added to the graph
	 * without an optimisation, which would move almost nothing, and enter the
	 * next one (a disagreeing closure's, or flushPendingClosures() at the end
	 * of the run). 0 = optimise at every accepted closure. */
	double optimize_min_closure_chi2 = 2.0;

	template <class V>
	void visit(V& v)
	{
		graph.visit(v);
		v.real("min_sequential_xy_std_m", min_sequential_xy_std_m, 1e-4, 10.0);
		v.degrees("min_sequential_yaw_std_deg", min_sequential_yaw_std_rad, 1e-3, 90.0);
		v.real("weak_xy_std_m", weak_xy_std_m, 0.0, 1000.0);
		v.degrees("weak_yaw_std_deg", weak_yaw_std_rad, 0.0, 180.0);
		v.real("loop_edge_covariance_factor", loop_edge_covariance_factor, 0.01, 1000.0);
		v.flag("detect_loops", detect_loops);
		v.real("optimize_min_closure_chi2", optimize_min_closure_chi2, 0.0, 1e6);
	}
};

/** What the front-end hands over for one keyframe. */
struct TKeyframe
{
	int64_t id = -1;  //!< the front-end's keyframe id
	mrpt::math::TPose2D pose;  //!< front-end (online) world pose
	/** Covariance of the motion from the previous keyframe, in the previous
	 * keyframe's frame (x, y, yaw), from the front-end matcher; ignored for
	 * the first keyframe. */
	Eigen::Matrix3d relative_covariance = Eigen::Matrix3d::Identity() * 1e-4;
	bool after_gap = false;  //!< odometry gap / lost tracking before this keyframe: weak edge
	int group = -1;  //!< tile index
	TPointCloud2D points;  //!< scan points in the robot frame (people already removed)
};

struct TKeyframeResult
{
	size_t node = 0;
	std::vector<TLoopClosure> closures;  //!< tested at this keyframe (accepted and rejected)
	bool optimized = false;
	TOptimizationReport optimization;
	double time_ms = 0;  //!< whole addKeyframe()
};

struct TBackendTiming
{
	size_t keyframes = 0, candidates_tested = 0, closures_accepted = 0, optimizations = 0;
	size_t closures_deferred = 0;  //!< accepted closures added without an optimisation of their own
	double total_ms = 0, detect_ms = 0, optimize_ms = 0;
	double max_keyframe_ms = 0, max_optimize_ms = 0;
};

class CGraphBackend
{
   public:
	CGraphBackend(const TGraphBackendOptions& options = {}, const TLoopClosureOptions& loopOptions = {});

	TKeyframeResult addKeyframe(const TKeyframe& keyframe);
	/** Optimises the graph if closures were added without an optimisation
	 * since the last one (optimize_min_closure_chi2); call at the end of a run
	 * before reading poses. Returns the report if it optimised. */
	std::optional<TOptimizationReport> flushPendingClosures();

	const CPoseGraph& graph() const { return m_graph; }
	/** Optimised world pose of every keyframe, in the order added. */
	std::vector<mrpt::math::TPose2D> optimizedPoses() const;
	/** Transform T with optimised = T (+) front-end pose, for the latest
	 * keyframe (identity before any closure). */
	mrpt::math::TPose2D correction() const;
	/** Every tested closure so far; status updated if the optimiser dropped it. */
	const std::vector<TLoopClosure>& closures() const { return m_closures; }
	const std::vector<TSubmap>& submaps() const { return m_detector.submaps(); }
	const CLoopClosureDetector& detector() const { return m_detector; }
	const TBackendTiming& timing() const { return m_timing; }

   private:
	size_t addNodeAndSequentialEdge(const TKeyframe& keyframe);
	CLoopClosureDetector::TRelativeCovariance relativeCovariances(size_t query) const;
	void addClosures(std::vector<TLoopClosure>& tested);
	void addLoopEdge(TLoopClosure& c);
	std::vector<size_t> confirmClosures(std::vector<TLoopClosure>& tested);
	void rememberVerified(size_t node, size_t firstNew);
	void markDroppedClosures(const TOptimizationReport& report);
	bool closuresNeedOptimization(size_t firstNewEdge) const;
	TOptimizationReport optimize();

	TGraphBackendOptions m_options;
	CPoseGraph m_graph;
	CLoopClosureDetector m_detector;
	std::vector<mrpt::math::TPose2D> m_frontendPoses;
	std::vector<TLoopClosure> m_closures;
	std::vector<size_t> m_recentVerified;  //!< m_closures indices: passed verification in the confirmation window
	TBackendTiming m_timing;
	size_t m_pendingLoopEdges = 0;  //!< loop edges added since the last optimisation
};

}  // namespace hslam::graph
