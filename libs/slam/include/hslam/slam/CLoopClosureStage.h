/* hslam: the loop-closure stage of the mapping pipeline (DESIGN.md figure 55:
 * "keyframe store -> pose graph -> loop closure -> optimisation"; issue 13).
 *
 * Per laser scan it receives the front-end's estimate (TPoseEstimate) and the
 * scan's range record. Every keyframe_every_m of estimated travel or
 * keyframe_every_deg of rotation the scan becomes a keyframe of the back-end
 * (libs/graph CGraphBackend): its points without the beams on people (the
 * dynamic filter's mask), the relative covariance since the previous keyframe
 * and whether an odometry gap / jump lies in between (a weak edge). The
 * back-end searches and verifies loop closures and optimises the graph when
 * one is accepted.
 *
 * Relative covariance of a keyframe edge: the front-end's covariance growth
 * since the previous keyframe (Sigma_k - Sigma_k-1, rotated into the previous
 * keyframe's frame, negative eigenvalues cut to zero), floored by a standard
 * deviation proportional to the travel (relative_xy_std_per_m) and rotation
 * (relative_yaw_std_deg_per_m, relative_yaw_std_per_rad). The UKF's absolute
 * covariance saturates while it matches, so its growth alone would call a
 * drifting chain exact; the floor keeps the chain covariance (which sizes the
 * loop search window and the consistency gate) as wide as the front-end's
 * real drift.
 *
 * For every scan it keeps the online pose and the keyframe it follows, so the
 * corrected pose of scan s following keyframe k is
 *     optimised_k (+) online_k^-1 (+) online_s.
 *
 * With background_thread (default) the back-end runs on its own thread
 * (common::CSerialWorker): keyframes are queued in order and handed to it one
 * by one, exactly as the direct call would, so trajectories, closures and
 * graph are the same bit for bit; only the wall time changes. Everything that
 * reads the back-end (backend(), correctedScanPoses(), optimized()) first
 * waits for the queue to drain, and a back-end error is rethrown there.
 *
 * INI: [loop_closure] = this stage's keys + graph::TLoopClosureOptions;
 *      [graph] = graph::TGraphBackendOptions. No file I/O. */
#pragma once

#include <hslam/common/CSerialWorker.h>
#include <hslam/common/range_data.h>
#include <hslam/graph/CGraphBackend.h>
#include <hslam/maps/CTiledGridGeometry.h>
#include <hslam/slam/CPoseEstimator.h>

#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace hslam::slam
{
/** [loop_closure]: the pipeline's switch, keyframe insertion, edge floors,
 * plus the detector's keys. */
struct TLoopClosureStageOptions
{
	bool enabled = true;  //!< run the back-end (see hslam-default.ini for the measured effect)
	double keyframe_every_m = 0.5;  //!< new keyframe after this estimated travel
	double keyframe_every_rad = mrpt::DEG2RAD(15.0);  //!< ... or this estimated rotation
	double relative_xy_std_per_m = 0.05;  //!< floor of an edge's xy sigma per metre of travel
	double relative_yaw_std_rad_per_m = mrpt::DEG2RAD(1.0);  //!< floor of its yaw sigma per metre
	double relative_yaw_std_per_rad = 0.05;  //!< ... plus this fraction of the rotation
	/** "growth": the front-end covariance's growth since the previous keyframe;
	 * "posterior": the front-end's covariance at this keyframe (its uncertainty
	 * against the local map the scan was matched to), both in the previous
	 * keyframe's frame and floored as above. */
	std::string edge_covariance = "posterior";
	bool rerender_map = true;  //!< re-insert every scan at its corrected pose at the end
	/** Run the back-end on a thread of its own (same results; the front-end
	 * does not wait for the loop-closure search). */
	bool background_thread = true;
	graph::TLoopClosureOptions detector;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.real("keyframe_every_m", keyframe_every_m, 0.01, 100.0);
		v.degrees("keyframe_every_deg", keyframe_every_rad, 0.1, 360.0);
		v.real("relative_xy_std_per_m", relative_xy_std_per_m, 0.0, 10.0);
		v.degrees("relative_yaw_std_deg_per_m", relative_yaw_std_rad_per_m, 0.0, 90.0);
		v.real("relative_yaw_std_per_rad", relative_yaw_std_per_rad, 0.0, 10.0);
		v.choice("edge_covariance", edge_covariance, {"growth", "posterior"});
		v.flag("rerender_map", rerender_map);
		v.flag("background_thread", background_thread);
		detector.visit(v);
	}
};

/** One back-end call made on the background thread. */
struct TBackendCallTiming
{
	double keyframe_ms = 0;  //!< the whole addKeyframe()
	double optimize_ms = -1;  //!< its optimisation, -1 if it did not optimise
};

class CLoopClosureStage
{
   public:
	CLoopClosureStage(const TLoopClosureStageOptions& options, const graph::TGraphBackendOptions& backendOptions,
					  const maps::CTiledGridGeometry& tiles);

	/** One scan: its estimate, range record and the beams to keep out of the
	 * keyframe points (people; may be null). Returns the back-end's result if
	 * the scan became a keyframe and the back-end runs on this thread; with
	 * background_thread the keyframe is queued and nothing is returned. */
	std::optional<graph::TKeyframeResult> process(const TPoseEstimate& estimate, const common::TRangeData& scan,
												  const std::vector<bool>* excludedBeams);

	/** Corrected pose of every scan processed (see file comment). */
	std::vector<mrpt::poses::CPose2D> correctedScanPoses() const;
	/** The graph has been optimised at least once (an accepted closure). */
	bool optimized() const { return backend().timing().optimizations > 0; }

	/** At the end of a run (or before reading poses mid-run): waits for the
	 * queue, then lets the back-end optimise closures it added without an
	 * optimisation (graph::TGraphBackendOptions::optimize_min_closure_chi2).
	 * Returns that optimisation's time in ms, or -1 if none was needed. */
	double flush();

	/** The back-end, once every keyframe queued so far has been processed. */
	const graph::CGraphBackend& backend() const;
	/** Returns once the background thread has processed every keyframe queued
	 * (at once without it); rethrows the back-end's error, if any. */
	void wait() const;
	/** Keyframes queued for the background thread and not yet processed (0 without it). */
	size_t queuedKeyframes() const { return m_worker ? m_worker->pending() : 0; }
	/** Time of each back-end call made on the background thread, in keyframe
	 * order (empty without it; waits first). */
	const std::vector<TBackendCallTiming>& backgroundTimings() const;
	const TLoopClosureStageOptions& options() const { return m_options; }
	const graph::TGraphBackendOptions& backendOptions() const { return m_backendOptions; }

   private:
	bool isKeyframe(const mrpt::math::TPose2D& pose) const;
	Eigen::Matrix3d relativeCovariance(const TPoseEstimate& estimate) const;
	int tileGroup(const mrpt::math::TPose2D& pose);

	TLoopClosureStageOptions m_options;
	graph::TGraphBackendOptions m_backendOptions;
	maps::CTiledGridGeometry m_tiles;
	graph::CGraphBackend m_backend;
	std::vector<mrpt::math::TPose2D> m_keyframeOnline;  //!< online pose of each keyframe (node order)
	Eigen::Matrix3d m_lastKeyframeCovariance = Eigen::Matrix3d::Zero();
	std::vector<mrpt::math::TPose2D> m_scanOnline;  //!< online pose of each scan
	std::vector<size_t> m_scanKeyframe;  //!< keyframe (node) each scan follows
	bool m_gapSinceKeyframe = false;
	std::unordered_map<maps::TTileIndex, int, maps::TTileIndexHash> m_tileGroups;  //!< tile -> group, first visit order
	std::vector<TBackendCallTiming> m_backgroundTimings;  //!< written by the worker only
	/** Last member: destroyed (and joined) before what its thread uses. */
	std::unique_ptr<common::CSerialWorker<graph::TKeyframe>> m_worker;
};

}  // namespace hslam::slam
