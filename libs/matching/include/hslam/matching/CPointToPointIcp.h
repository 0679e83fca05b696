/* hslam: point-to-point ICP with the semantics of MRPT's classic ICP
 * (mrpt::slam::CICP, ICP_Method_Classic: nearest-neighbour pairs within a
 * distance threshold that grows with range, unique pairs, the closed-form
 * SE(2) least-squares step, thresholds shrunk by ALFA whenever the pose stops
 * moving, until smallest_threshold_dist_m), at a fraction of its cost:
 *
 *  - the reference is a CPointIndex2D built once per keyframe window, not a
 *    CSimplePointsMap whose k-d tree MRPT rebuilds whenever it is refilled;
 *  - each scan point keeps the k nearest reference points of its last tree
 *    query. At the next iteration the point has moved by delta; if the
 *    nearest cached candidate is within r_k - delta (r_k the distance of the
 *    k-th candidate at the last query), no other reference point can be
 *    nearer (triangle inequality), so the answer is exact without a tree
 *    query. Most ICP iterations move points by millimetres: most queries are
 *    answered from the cache. Likewise, a point whose nearest reference
 *    point was r_1 away is unpaired while r_1 - delta is at least its
 *    pairing limit (clutter, parts of the room the reference never saw):
 *    one tree query, then none;
 *  - unique pairs are found in one pass over the pairs (a slot per
 *    reference point), not by sorting them;
 *  - optionally (stage_step_fraction > 0), a pairing stage other than the
 *    last ends once a step is below that fraction of its pairing distance:
 *    MRPT iterates every stage to 1e-6, though the next, tighter stage
 *    refines the pose anyway (iterations on the CARMEN logs 37 -> 23 per
 *    call at 0.01). 0 keeps MRPT's semantics exactly.
 *
 * Used by CIcpMatcher (engine = cached) in the default front-end (issue 12,
 * "Speed"). No I/O. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::matching
{
class CPointToPointIcp
{
   public:
	struct TOptions
	{
		int max_iterations = 80;
		double threshold_dist_m = 0.5;  //!< initial pairing distance (MRPT thresholdDist)
		double threshold_ang_rad = 5.0 * M_PI / 180.0;  //!< pairing distance growth per metre of range (MRPT thresholdAng)
		double alfa = 0.6;  //!< threshold shrink factor (MRPT ALFA)
		double smallest_threshold_dist_m = 0.05;  //!< final pairing distance
		double min_step_m = 1e-6;  //!< "the pose stopped moving" (MRPT minAbsStep_trans)
		double min_step_rad = 1e-6;  //!< (MRPT minAbsStep_rot)
		bool only_unique_robust = true;  //!< each reference point keeps only its closest pair
		int decimation = 1;  //!< every k-th scan point, offset rotating per threshold step
		int cached_neighbours = 4;  //!< candidates kept per scan point between tree queries
		double stage_step_fraction = 0;  //!< a non-final stage ends at steps below this x its pairing distance
	};

	struct TResult
	{
		mrpt::poses::CPose2D pose;  //!< pose of the scan in the reference frame
		double goodness = 0;  //!< fraction of scan points paired at the last iteration
		int iterations = 0;
		size_t tree_queries = 0;  //!< nearest-neighbour queries that needed the index
		size_t cached_answers = 0;  //!< queries answered exactly from the cache
	};

	CPointToPointIcp() : CPointToPointIcp(TOptions()) {}
	explicit CPointToPointIcp(const TOptions& options) : m_options(options) {}

	/** Aligns the n scan points (robot frame, xs / ys) to `reference`,
	 * starting at `seed`. */
	TResult align(const CPointIndex2D& reference, const float* xs, const float* ys, size_t n,
				  const mrpt::poses::CPose2D& seed) const;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace hslam::matching
