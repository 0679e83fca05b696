/* hslam graph: loop-closure detection and verification (issue 13, part 2).
 *
 * Keyframes are grouped into submaps of `submap_keyframes` consecutive
 * keyframes; a finished submap keeps its points in the frame of its middle
 * keyframe (the anchor), voxel-thinned to the matcher's resolution, and its
 * likelihood field is built when first matched (kept in a small LRU cache).
 *
 * Candidates for the current keyframe: finished submaps not among the recent
 * ones whose anchor lies within the overlap distance plus the search window of
 * the current estimate. The window is `window_sigmas` times the relative
 * uncertainty of the current pose with respect to the anchor (given by the
 * caller: the back-end's Dijkstra projection through the graph, small after
 * a short loop or near a closed one, large after a long unclosed loop or an
 * odometry gap, so a large drift is still searched), clamped to the options.
 * A candidate whose closure would tell the graph less than
 * min_information_gain_nats (closureInformationGain: the graph already knows
 * the relative pose about as well as a closure would) is not tested.
 *
 * Verification (every test must pass; a rejected candidate keeps the reason
 * of the first test it failed; they run in the order 1, 2, 3, 5, 4, so the
 * score-surface covariance that 4 needs is computed for few candidates):
 *  1. score: the correlative match's mean likelihood >= min_score and hit
 *     fraction >= min_hit_fraction (overlap), with >= min_query_points points;
 *  2. ICP agreement: MRPT CICP from the correlative pose converges with
 *     goodness >= min_icp_goodness and moves less than the agreement limits;
 *  3. free side (free_space_check.h): at the matched pose at least
 *     min_free_side_fraction of the query's beams that end on a submap wall
 *     reach it through space the submap's own beams crossed (a wall is not
 *     seen from behind);
 *  4. consistency: the correction the closure implies for the current pose is
 *     within the chi2 gate of that relative covariance plus the closure's;
 *  5. uniqueness: no other pose in the window, its translation widened by
 *     ambiguity_window_factor (outside a small exclusion around the best),
 *     reaches ambiguity_ratio x the best score (repeated rooms, corridors).
 * With max_tracked_in_a_row > 0 (off by default), a submap whose closure
 * the keyframe before kept (confirmed by the back-end, still in the graph)
 * is tracked: the keyframe's pose in its anchor's frame is that closure's
 * composed with the graph's motion since, known to a few centimetres, so
 * test 1 searches two cells and two rotation steps around it instead of the
 * window (CCorrelativeScanMatcher::matchNear), and test 5 is skipped (the
 * closure tracked passed it, 0.5 m back). Every max_tracked_in_a_row + 1-th closure of a run is
 * searched in full again.
 * Then the back-end (CGraphBackend) asks for a second opinion: a closure that
 * passed is held ("awaiting confirmation") until another one, from the same
 * or one of the next confirm_within_keyframes keyframes, asks the graph for
 * the same correction (within confirm_xy_m / confirm_yaw_deg); then both are
 * added and the graph optimised. One that finds no partner stays out ("not
 * confirmed"). The graph's robust step may still drop an added edge (reason
 * "dropped by optimiser"). */
#pragma once

#include <hslam/common/CTaskPool.h>
#include <hslam/graph/CCorrelativeScanMatcher.h>
#include <hslam/graph/CPoseGraph.h>
#include <hslam/graph/free_space_check.h>

#include <functional>
#include <list>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <vector>

namespace hslam::graph
{
struct TLoopClosureOptions
{
	/** Field and query keys (resolution_m, kernel_sigma_m, levels, ...); the
	 * query reaches 10 m and the covariance spans +-2 cells by default (the
	 * matcher's own defaults: all points, +-4). */
	TCorrelativeMatcherOptions matcher = closureMatcher();
	static TCorrelativeMatcherOptions closureMatcher()
	{
		TCorrelativeMatcherOptions m;
		m.max_query_range_m = 10.0;
		m.covariance_span_cells = 2;  // the surface is sharp: +-2 cells measure what +-4 did
		return m;
	}
	int submap_keyframes = 10;  //!< consecutive keyframes per submap
	int min_separation_keyframes = 30;  //!< submaps with a keyframe this recent are not candidates
	int detect_every_n_keyframes = 1;  //!< search at every n-th keyframe
	int max_candidates = 3;  //!< submaps matched per search (nearest first)
	/** A submap whose search ended with a low score is not searched again
	 * from the next this-many-minus-one keyframes (its slot among
	 * max_candidates stays spent); 1 = every time. */
	int retest_low_score_after_keyframes = 1;
	/** A submap whose search over the widest window (the translation window
	 * clamped at max_window_xy_m: the prior no longer bounds where the
	 * keyframe is) ended with a low score is not searched over it again from
	 * the next this-many-minus-one keyframes (its slot stays spent); 1 =
	 * every time. Such searches cost 5-20x a narrow one. */
	int retest_wide_after_keyframes = 2;
	/** A search stops once this many of its candidates were accepted (the
	 * rest, farther away, add little once the keyframe is tied to the old
	 * map); 0 = every candidate is matched. */
	int max_closures_per_keyframe = 0;
	double overlap_distance_m = 6.0;  //!< anchor within this (plus the window) of the current pose
	double window_sigmas = 3.0;  //!< window = this x the relative standard deviation
	double min_window_xy_m = 0.5, max_window_xy_m = 4.0;
	double min_window_yaw_rad = mrpt::DEG2RAD(10.0), max_window_yaw_rad = mrpt::DEG2RAD(45.0);
	double min_score = 0.55;  //!< mean likelihood of the query points
	double min_hit_fraction = 0.6;  //!< fraction of query points on the submap (overlap)
	int min_query_points = 50;
	double ambiguity_ratio = 0.75;  //!< a second peak at this fraction of the best rejects the closure
	double ambiguity_xy_m = 0.5, ambiguity_yaw_rad = mrpt::DEG2RAD(10.0);  //!< what counts as "another" peak
	/** The second peak is looked for over the search window's translation
	 * times this: a place repeated just outside the window (the true one,
	 * when the graph's uncertainty is understated) must make the one inside
	 * ambiguous, not unique. */
	double ambiguity_window_factor = 1.5;
	bool ambiguity_thinned = false;  //!< the second-peak search scores the thinned search query
	double min_icp_goodness = 0.7;
	double icp_max_shift_m = 0.15, icp_max_shift_yaw_rad = mrpt::DEG2RAD(2.0);
	double consistency_chi2 = 16.27;  //!< 3-dof chi2 gate (99.9 %) of the implied correction
	double min_free_side_fraction = 0.5;  //!< of the query's wall hits that must come from the submap's free side
	int max_cached_fields = 4;  //!< likelihood fields kept in memory
	/** Threads that verify one keyframe's candidates at once, this one
	 * included (0: one per hardware thread, at most max_candidates; 1: one
	 * after the other). The candidates are independent: the closures are the
	 * same for any value. */
	int search_threads = 0;
	int confirm_within_keyframes = 10;  //!< a closure waits this long for a second that agrees (0: none needed)
	double confirm_xy_m = 0.3, confirm_yaw_rad = mrpt::DEG2RAD(3.0);  //!< agreement of two closures' corrections
	/** A candidate is tested only if a closure of the typical accuracy below
	 * would tell the graph at least this much (nats; 0 tests every one). */
	double min_information_gain_nats = 1.0;
	double closure_xy_std_m = 0.05, closure_yaw_std_rad = mrpt::DEG2RAD(1.0);  //!< typical closure accuracy
	/** A submap whose closure the keyframe before kept (confirmed, in the
	 * graph) is verified from where that closure and the front-end's motion
	 * since put this keyframe: a search of two cells and two rotation steps
	 * instead of the window's, and no second-peak search (the closure it follows
	 * passed one). Every other test stays. After this many tracked closures
	 * in a row the next is searched in full again; 0 = never tracked. */
	int max_tracked_in_a_row = 0;

	template <class V>
	void visit(V& v)
	{
		matcher.visitGrid(v);
		v.integer("submap_keyframes", submap_keyframes, 1, 1000);
		v.integer("min_separation_keyframes", min_separation_keyframes, 1, 100000);
		v.integer("detect_every_n_keyframes", detect_every_n_keyframes, 1, 1000);
		v.integer("max_candidates", max_candidates, 1, 100);
		v.integer("retest_low_score_after_keyframes", retest_low_score_after_keyframes, 1, 1000);
		v.integer("retest_wide_after_keyframes", retest_wide_after_keyframes, 1, 1000);
		v.integer("max_closures_per_keyframe", max_closures_per_keyframe, 0, 100);
		v.real("overlap_distance_m", overlap_distance_m, 0.0, 100.0);
		v.real("window_sigmas", window_sigmas, 0.0, 100.0);
		v.real("min_window_xy_m", min_window_xy_m, 0.0, 100.0);
		v.real("max_window_xy_m", max_window_xy_m, 0.0, 100.0);
		v.degrees("min_window_yaw_deg", min_window_yaw_rad, 0.0, 180.0);
		v.degrees("max_window_yaw_deg", max_window_yaw_rad, 0.0, 180.0);
		v.real("min_score", min_score, 0.0, 1.0);
		v.real("min_hit_fraction", min_hit_fraction, 0.0, 1.0);
		v.integer("min_query_points", min_query_points, 1, 100000);
		v.real("ambiguity_ratio", ambiguity_ratio, 0.0, 1.0);
		v.real("ambiguity_xy_m", ambiguity_xy_m, 0.0, 100.0);
		v.real("ambiguity_window_factor", ambiguity_window_factor, 1.0, 10.0);
		v.flag("ambiguity_thinned", ambiguity_thinned);
		v.degrees("ambiguity_yaw_deg", ambiguity_yaw_rad, 0.0, 180.0);
		v.real("min_icp_goodness", min_icp_goodness, 0.0, 1.0);
		v.real("icp_max_shift_m", icp_max_shift_m, 0.0, 10.0);
		v.degrees("icp_max_shift_deg", icp_max_shift_yaw_rad, 0.0, 180.0);
		v.real("consistency_chi2", consistency_chi2, 0.0, 1e9);
		v.real("min_free_side_fraction", min_free_side_fraction, 0.0, 1.0);
		v.integer("max_cached_fields", max_cached_fields, 1, 10000);
		v.integer("search_threads", search_threads, 0, 256);
		v.integer("confirm_within_keyframes", confirm_within_keyframes, 0, 1000);
		v.real("confirm_xy_m", confirm_xy_m, 0.0, 100.0);
		v.degrees("confirm_yaw_deg", confirm_yaw_rad, 0.0, 180.0);
		v.real("min_information_gain_nats", min_information_gain_nats, 0.0, 100.0);
		v.real("closure_xy_std_m", closure_xy_std_m, 1e-4, 10.0);
		v.degrees("closure_yaw_std_deg", closure_yaw_std_rad, 0.01, 90.0);
		v.integer("max_tracked_in_a_row", max_tracked_in_a_row, 0, 1000);
	}
};

/** Consecutive keyframes with their points in the anchor's frame. */
struct TSubmap
{
	size_t first_node = 0, last_node = 0, anchor_node = 0;
	TPointCloud2D points;  //!< anchor frame, thinned to one point per cell
	std::vector<TSubmapView> views;  //!< each keyframe's origin and points in the anchor frame (its free space)
};

/** A tested candidate: accepted or rejected, with its figures. */
struct TLoopClosure
{
	size_t query_node = 0, anchor_node = 0, submap = 0;
	int64_t query_keyframe_id = -1, anchor_keyframe_id = -1;
	mrpt::math::TPose2D relative;  //!< measured pose of the query in the anchor's frame
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  //!< of `relative` (when has_covariance)
	bool has_covariance = false;  //!< computed: the closure passed every test before the consistency gate
	mrpt::math::TPose2D query_pose_estimate;  //!< world pose of the query when tested
	mrpt::math::TPose2D query_pose_matched;  //!< world pose the closure implies (anchor (+) relative)
	mrpt::math::TPose2D anchor_pose;  //!< world pose of the anchor when tested
	double window_xy_m = 0, window_yaw_rad = 0;
	double prior_xy_std_m = 0, prior_yaw_std_rad = 0;  //!< relative std of query vs anchor before the test (largest xy axis)
	double information_gain_nats = 0;  //!< what a typical closure would tell the graph (closureInformationGain)
	double score = 0, hit_fraction = 0, second_score = 0;
	double icp_goodness = 0, icp_shift_m = 0, icp_shift_yaw_rad = 0;
	double consistency_chi2 = 0;
	double free_side_fraction = 1;  //!< of the query's wall hits at the matched pose, through the submap's free space
	/** Verified from the closure of the same submap at the keyframe before
	 * (max_tracked_in_a_row), not by a search; how many in a row. */
	int tracked_in_a_row = 0;
	bool accepted = false;
	std::string reason;  //!< "accepted" or why not
	double match_ms = 0;
	long edge = -1;  //!< graph edge index once added
};

/** The CSV header and one row per closure (for the pipeline's closures.csv). */
std::string loopClosureCsvHeader();
std::string loopClosureCsvRow(const TLoopClosure& c);

class CLoopClosureDetector
{
   public:
	using TOptions = TLoopClosureOptions;

	explicit CLoopClosureDetector(const TOptions& options = TOptions());
	~CLoopClosureDetector();

	/** Records the points (robot frame) of a node just added to `graph`;
	 * closes a submap every submap_keyframes nodes (poses taken from `graph`). */
	void addKeyframe(size_t node, const TPointCloud2D& points, const CPoseGraph& graph);

	/** Covariance (world frame) of the query node's pose with the given
	 * anchor node held fixed; no value when the two are not connected. */
	using TRelativeCovariance = std::function<std::optional<Eigen::Matrix3d>(size_t anchorNode)>;

	/** Candidates for `node` (its points given to addKeyframe) and their
	 * verification; `relativeCovariance` sizes each search window and gates
	 * the correction a closure implies. */
	std::vector<TLoopClosure> detect(size_t node, const CPoseGraph& graph, const TRelativeCovariance& relativeCovariance);

	/** The closures tested at `node` as the back-end kept them (after its
	 * confirmation and optimiser): the accepted ones are tracked at the next
	 * keyframe (max_tracked_in_a_row); the tracks of earlier keyframes end. */
	void keepTracks(size_t node, const std::vector<TLoopClosure>& closures);

	const std::vector<TSubmap>& submaps() const { return m_submaps; }
	const TOptions& options() const { return m_options; }
	/** Candidates in range that were not tested: a closure would have told
	 * the graph less than min_information_gain_nats. */
	size_t skippedLittleInformation() const { return m_skippedLittleInformation; }
	/** Candidates not searched: their last search, a few keyframes ago, ended
	 * with a low score (retest_low_score_after_keyframes). */
	size_t skippedRecentLowScore() const { return m_skippedRecentLowScore; }
	/** Candidates not searched: their last search over the widest window, a
	 * few keyframes ago, ended with a low score (retest_wide_after_keyframes). */
	size_t skippedRecentWide() const { return m_skippedRecentWide; }

   private:
	struct TCandidate;
	struct TSubmapField;
	/** A closure kept at the keyframe before: where it put that keyframe. */
	struct TClosureTrack
	{
		size_t node = 0;
		mrpt::math::TPose2D relative;  //!< that keyframe in the anchor's frame
		int in_a_row = 0;  //!< tracked closures ending with this one
	};
	std::vector<TCandidate> candidates(size_t node, const CPoseGraph& graph,
									   const TRelativeCovariance& relativeCovariance);
	/** The candidates to search now (not skipped after a recent low score
	 * or a recent low-score search over the widest window). */
	std::vector<TCandidate> searched(size_t node, const CPoseGraph& graph,
									 const TRelativeCovariance& relativeCovariance);
	/** Whether lastAt holds `submap` at a node less than `keyframes` before `node`. */
	static bool within(const std::map<size_t, size_t>& lastAt, size_t submap, size_t node, int keyframes);
	/** Whether a translation window is the widest one (clamped at max_window_xy_m). */
	bool isWide(double window_xy_m) const;
	/** verify() of every candidate, at most max_cached_fields at a time (their
	 * fields stay cached while the pool's threads read them). */
	std::vector<TLoopClosure> verifyAll(const std::vector<TCandidate>& cands, size_t node, const CPoseGraph& graph);
	TLoopClosure verify(const TCandidate& c, const TSubmapField& field, size_t node, const CPoseGraph& graph) const;
	bool matchBest(const CCorrelativeScanMatcher& m, const TCandidate& c, TLoopClosure& out,
				   TCorrelativeMatch& best) const;
	/** matchNear() around where the candidate's track and the graph's
	 * motion since put the keyframe; the same score tests as matchBest(). */
	bool matchTracked(const CCorrelativeScanMatcher& m, const TCandidate& c, const CPoseGraph& graph,
					  TLoopClosure& out, TCorrelativeMatch& best) const;
	bool checkUniqueness(const CCorrelativeScanMatcher& m, const TCandidate& c, const TCorrelativeMatch& best,
						 TLoopClosure& out) const;
	bool checkConsistency(const TCandidate& c, TLoopClosure& out) const;
	bool checkFreeSide(const TSubmapField& field, TLoopClosure& out) const;
	bool refineWithIcp(const TSubmapField& field, TLoopClosure& out) const;
	void closeSubmap(const CPoseGraph& graph);
	/** The submap's field from the LRU cache, made most recent; a field not
	 * cached gets a slot (the least recently used one's buffers) and
	 * needsBuild = true: buildField() fills it. */
	TSubmapField* cachedField(size_t submap, bool& needsBuild);
	/** Rasterises the submap into the field: likelihood levels, free space, ICP points. */
	void buildField(TSubmapField& field, size_t submap) const;

	TOptions m_options;
	std::vector<TSubmap> m_submaps;
	std::vector<std::pair<size_t, TPointCloud2D>> m_pending;  //!< nodes of the open submap
	TPointCloud2D m_queryPoints;  //!< points of the last added keyframe
	TPreparedQuery m_query;  //!< the same, as every search of its candidates reads them
	size_t m_queryNode = 0;
	size_t m_skippedLittleInformation = 0;
	size_t m_skippedRecentLowScore = 0;
	std::map<size_t, size_t> m_lowScoreAt;  //!< submap -> keyframe node of its last low-score search
	size_t m_skippedRecentWide = 0;
	std::map<size_t, size_t> m_wideLowScoreAt;  //!< submap -> keyframe node of its last low-score widest search
	std::map<size_t, TClosureTrack> m_tracks;  //!< submap -> the keyframe before's kept closure
	std::list<std::pair<size_t, std::unique_ptr<TSubmapField>>> m_fieldCache;  //!< most recent first
	std::unique_ptr<common::CTaskPool> m_pool;  //!< verifies a keyframe's candidates side by side
};

/** Mutual information (nats) between the graph's relative pose of a query
 * and an anchor (covariance `relative`) and a closure measuring it with the
 * diagonal covariance of the given standard deviations:
 * 0.5 ln(det(relative + closure) / det(closure)) (Ila, Porta and
 * Andrade-Cetto, "Information-based compact pose SLAM", T-RO 2010, eq. 17).
 * Near 0 when the graph already knows the relative pose as well as a closure
 * would tell it (just after a closure of the same place). */
double closureInformationGain(const Eigen::Matrix3d& relative, double closureXyStd_m, double closureYawStd_rad);

/** The largest variance (m^2) of the xy block of a pose covariance: its
 * worst-constrained direction. */
double largestXyVariance(const Eigen::Matrix3d& covariance);

/** Whether two verified closures ask `graph` (its current poses) for the same
 * correction: b's measured pose against b's query pose moved by the
 * world-frame correction a implies at its own query, within xy_m / yaw_rad. */
bool closuresAgree(const TLoopClosure& a, const TLoopClosure& b, const CPoseGraph& graph, double xy_m, double yaw_rad);

}  // namespace hslam::graph
