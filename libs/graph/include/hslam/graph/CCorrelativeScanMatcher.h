/* hslam graph: multi-resolution correlative scan matching with
 * branch-and-bound (Olson, "Real-time correlative scan matching", ICRA 2009;
 * Hess et al., "Real-time loop closure in 2D LIDAR SLAM", ICRA 2016, section V,
 * Cartographer's FastCorrelativeScanMatcher2D).
 *
 * The reference (a submap: several keyframes' points in one frame) is
 * rasterised once into a likelihood field with max-pooled levels
 * (CMultiResolutionGrid). A query (points in the robot frame) is matched over a
 * window (x, y, yaw) around a guess: every rotation of the window (step from
 * the farthest query point, so the far end moves at most one cell) and every
 * integer cell offset; branch-and-bound over the levels finds the offset of
 * highest mean likelihood exactly, visiting a tiny part of the window. The
 * winner is refined below one cell on the bilinear field (parabola fits), and
 * its covariance comes from the score surface around it (Olson section IV-C:
 * the field read as a likelihood, exp(-chi2/2) weights over a neighbourhood).
 *
 * Points are std::vector<mrpt::math::TPoint2Df> (float x, y in metres): the
 * query in the robot frame, the reference in the submap frame; the resulting
 * pose is the robot's pose in the reference frame. No I/O. */
#pragma once

#include <hslam/graph/CMultiResolutionGrid.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/TPose2D.h>

#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace hslam::graph
{
using TPointCloud2D = std::vector<mrpt::math::TPoint2Df>;

struct TCorrelativeMatcherOptions
{
	double resolution_m = 0.05;  //!< finest cell of the likelihood field
	double kernel_sigma_m = 0.05;  //!< sigma of the field around each reference point
	int levels = 7;  //!< finest + max-pooled levels (7: blocks up to 64 cells = 3.2 m at 5 cm)
	double window_xy_m = 1.0;  //!< default half-width of the translation window
	double window_yaw_rad = mrpt::DEG2RAD(30.0);  //!< default half-width of the rotation window
	double max_query_range_m = 0;  //!< query points farther from the robot are dropped (0 = keep all)
	double min_score = 0.3;  //!< no match below this mean likelihood (also the initial B&B bound)
	double covariance_span_cells = 4;  //!< half-width (cells / angle steps) of the score surface for the covariance
	/** The search for the best pose (not its refinement, not the covariance,
	 * not a search with an exclusion) uses the query thinned by
	 * adaptiveVoxelFilter to at least this many points (0 = all points),
	 * cells up to search_max_voxel_m. */
	int search_min_points = 100;
	double search_max_voxel_m = 0.9;

	/** The keys of the field and query (no window, no threshold). */
	template <class V>
	void visitGrid(V& v)
	{
		v.real("resolution_m", resolution_m, 0.01, 1.0);
		v.real("kernel_sigma_m", kernel_sigma_m, 0.005, 1.0);
		v.integer("levels", levels, 1, 12);
		v.real("max_query_range_m", max_query_range_m, 0.0, 100.0);
		v.real("covariance_span_cells", covariance_span_cells, 1.0, 20.0);
		v.integer("search_min_points", search_min_points, 0, 100000);
		v.real("search_max_voxel_m", search_max_voxel_m, 0.01, 10.0);
	}
	template <class V>
	void visit(V& v)
	{
		visitGrid(v);
		v.real("window_xy_m", window_xy_m, 0.0, 100.0);
		v.degrees("window_yaw_deg", window_yaw_rad, 0.0, 180.0);
		v.real("min_score", min_score, 0.0, 1.0);
	}
};

/** Half-widths of a search window around the guess. */
struct TSearchWindow
{
	double xy_m = 1.0;
	double yaw_rad = mrpt::DEG2RAD(30.0);
};

/** Poses within xy_m and yaw_rad of `centre` are left out of the search (for
 * the second-best peak of an ambiguity test). */
struct TSearchExclusion
{
	mrpt::math::TPose2D centre;
	double xy_m = 0.5;
	double yaw_rad = mrpt::DEG2RAD(10.0);
	/** Return the first pose found above the minimum score rather than the
	 * best: enough to tell whether a second peak exists. */
	bool first_above_min_score = false;
	/** Score the thinned search query (as the search for the best does)
	 * instead of every point; the bound is then on that query's score. */
	bool thinned_query = false;
};

struct TCorrelativeMatch
{
	bool found = false;  //!< a pose with score >= the minimum score exists in the window
	mrpt::math::TPose2D pose;  //!< robot pose in the reference frame (refined)
	double score = 0;  //!< mean likelihood of the query points at `pose`, 0..1
	double hit_fraction = 0;  //!< fraction of query points within ~1.2 kernel sigma of a reference point
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  //!< of `pose` (x, y, yaw), m^2 / rad^2
	size_t query_points = 0;  //!< points used after range filtering
	size_t search_points = 0;  //!< of those, scored by branch-and-bound (after thinning)
	size_t rotations = 0;  //!< rotations in the window
	size_t nodes_scored = 0;  //!< B&B nodes scored (cost measure)
	/** Score of the best branch-and-bound leaf (the thinned search query on the
	 * finest level, before refinement): the scale a second search with
	 * TSearchExclusion::thinned_query compares against. */
	double search_score = 0;
	double angle_step_rad = 0;  //!< rotation step of the search (for covarianceOf)
};

/** A query as match() uses it: the points within max_query_range_m of the
 * robot, and those thinned (adaptiveVoxelFilter) for the search for the best
 * pose. A keyframe matched against several submaps, and searched twice in
 * each (best pose, second peak), is prepared once (prepareQuery()): the
 * thinning alone was 3.8 % of intel's whole process when every search
 * repeated it. */
struct TPreparedQuery
{
	TPointCloud2D points;  //!< within max_query_range_m (all if 0)
	TPointCloud2D thinned;  //!< `points` thinned to search_min_points (cells up to search_max_voxel_m)
	double farthest_m = 0;  //!< range of the farthest of `points` (sets the rotation step)
};

/** What match() computes beyond the pose: the score-surface covariance costs
 * (2 k + 1)^3 evaluations of the query, more than the search itself for a
 * small window, so a caller that may reject the match first asks for the pose
 * only and calls covarianceOf() for the matches it keeps. */
enum class EMatchOutput
{
	pose_only,
	pose_and_covariance
};

/** -2 log(max(l, e^-4.5)) for a likelihood l in [0, 1], linearly
 * interpolated in a table of 8192 intervals (error below 3e-5 per point, at
 * the floor; the score-surface covariance sums it over every point at 729
 * poses, where std::log was most of a loop-closure test's time). */
class CNegLogTable
{
   public:
	CNegLogTable();
	double operator()(double l) const
	{
		const double u = std::clamp(l, 0.0, 1.0) * kIntervals;
		const int i = std::min(static_cast<int>(u), kIntervals - 1);
		const double f = u - i;
		return m_table[static_cast<size_t>(i)] * (1 - f) + m_table[static_cast<size_t>(i) + 1] * f;
	}

   private:
	static constexpr int kIntervals = 8192;
	std::vector<double> m_table;
};

class CCorrelativeScanMatcher
{
   public:
	using TOptions = TCorrelativeMatcherOptions;

	explicit CCorrelativeScanMatcher(const TOptions& options = TOptions());

	/** Builds the likelihood field of the reference points (submap frame). */
	void setReference(const TPointCloud2D& referencePoints);
	bool hasReference() const { return !m_grid.empty(); }
	const CMultiResolutionGrid& grid() const { return m_grid; }

	/** The query as every search reads it (see TPreparedQuery). */
	static TPreparedQuery prepareQuery(const TPointCloud2D& query, const TOptions& options);
	TPreparedQuery prepareQuery(const TPointCloud2D& query) const { return prepareQuery(query, m_options); }

	/** Best pose within the options' window around `guess`. */
	TCorrelativeMatch match(const TPointCloud2D& query, const mrpt::math::TPose2D& guess) const;
	/** Best pose within `window` around `guess`, optionally outside `exclude`
	 * and only if its score reaches `minScore` (< 0: the options' min_score).
	 * Without `exclude`, branch-and-bound scores the query thinned to
	 * search_min_points (each node scores every point: the search's cost is
	 * linear in them) and the winner is refined and scored with every point.
	 * With `exclude` (a second peak, the uniqueness test) every point is
	 * searched: a thinned query tells similar places apart less well (a
	 * thinned second search let two closures 2 m wrong through on the
	 * simulated laser-only sample). */
	TCorrelativeMatch match(const TPointCloud2D& query, const mrpt::math::TPose2D& guess, const TSearchWindow& window,
							const TSearchExclusion* exclude = nullptr, double minScore = -1,
							EMatchOutput output = EMatchOutput::pose_and_covariance) const;
	/** The same for a query prepared once (prepareQuery(), same options). */
	TCorrelativeMatch match(const TPreparedQuery& query, const mrpt::math::TPose2D& guess, const TSearchWindow& window,
							const TSearchExclusion* exclude = nullptr, double minScore = -1,
							EMatchOutput output = EMatchOutput::pose_and_covariance) const;

	/** match() in a window of two cells and two rotation steps around
	 * `guess` (125 leaves): for a pose already known to a few centimetres,
	 * e.g. a closure tracked from the keyframe before. No covariance
	 * (covarianceOf() gives it). */
	TCorrelativeMatch matchNear(const TPointCloud2D& query, const mrpt::math::TPose2D& guess, double minScore = -1) const;
	TCorrelativeMatch matchNear(const TPreparedQuery& query, const mrpt::math::TPose2D& guess, double minScore = -1) const;

	/** Score-surface covariance of a match found by match() or matchNear() for `query`. */
	Eigen::Matrix3d covarianceOf(const TPointCloud2D& query, const TCorrelativeMatch& m) const;
	Eigen::Matrix3d covarianceOf(const TPreparedQuery& query, const TCorrelativeMatch& m) const;

	/** Mean likelihood of the query at `pose` (bilinear on the finest level),
	 * and optionally the hit fraction. */
	double scoreAt(const TPointCloud2D& query, const mrpt::math::TPose2D& pose, double* hitFraction = nullptr) const;

	const TOptions& options() const { return m_options; }
	/** The points within max_query_range_m of the origin (all if 0): what
	 * match() keeps of a query. */
	TPointCloud2D filteredQuery(const TPointCloud2D& query) const;

   private:
	/** The finest level's cells (x0 + i, y0 + j), i, j < size, as doubles (row j). */
	void loadPatch(int x0, int y0, int size, std::vector<double>& patch) const;
	/** Adds one point's -2 log likelihood at n x n whole-cell offsets to `slice`
	 * (index i n + j), its bilinear fractions fx, fy within the patch's first cell. */
	void addPointChi2(const double* patch, int n, double fx, double fy, double* slice) const;
	void refine(const TPointCloud2D& query, double angleStep_rad, TCorrelativeMatch& m) const;
	Eigen::Matrix3d scoreSurfaceCovariance(const TPointCloud2D& query, const mrpt::math::TPose2D& pose,
										   double angleStep_rad) const;
	std::vector<double> scoreSurfaceChi2(const TPointCloud2D& query, const mrpt::math::TPose2D& pose,
										 double angleStep_rad, int k) const;

	TOptions m_options;
	CMultiResolutionGrid m_grid;
	CNegLogTable m_negLog;
};

}  // namespace hslam::graph
