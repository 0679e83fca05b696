/* hslam: short-memory world-frame evidence of static structure for the
 * dynamic object filter (beyond the thesis: 4.7.2 tells static from moving
 * objects only by the motion of their track, which pose errors and tracks
 * hopping between neighbouring chair legs imitate).
 *
 * A fine grid (resolution_m, 5 cm) keeps, per cell hit by a beam end point,
 * the current RUN of hits (hits at most max_gap_s apart: continuous presence)
 * and the number of distinct scans in it. A cell becomes ESTABLISHED when a
 * run has at least min_scans scans spread over at least min_span_s: something
 * stands there. Human gait: a foot is planted for less than ~0.7 s per step
 * (stance ~60 % of a ~1.1 s gait cycle) and at laser height the shin rotates
 * over it, so a walking leg leaves transient occupancy that never spans
 * min_span_s (1.0 s) in one place; the run gap keeps two passes over the same
 * spot (a person walking back along a path) from adding up. A chair or table
 * leg seen from a moving robot is established within ~1 s, whichever track
 * happens to be associated with it.
 *
 * staticSince(p) gives the earliest time a cell within radius_m of p (pose /
 * ICP error) became established. The trackers (CKalmanTracker::update) do
 * not confirm a track as dynamic on an observation on established structure,
 * and never confirm one with (more than confirm_max_static_fraction of its)
 * observations on structure established BEFORE the track was born: that is
 * static clutter. Structure established later may be the track's own object
 * standing still (a person waiting is legitimately static for mapping; once
 * it walks off, its observations are on new cells again).
 *
 * Short memory: established cells survive occlusions (gaps) up to memory_s;
 * a cell not hit for memory_s is forgotten (and pruned). Beams of confirmed
 * dynamic objects are not inserted (insert()'s skip mask). */
#pragma once

#include <hslam/common/cell_key.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace hslam::dynamic
{
class CStaticEvidenceGrid
{
   public:
	struct TOptions
	{
		double resolution_m = 0.05;  //!< cell side
		double radius_m = 0.10;  //!< search radius around an observation (pose error)
		int min_scans = 5;  //!< distinct scans that hit a cell ...
		double min_span_s = 1.0;  //!< ... spread over at least this time (> a planted foot, 0.7 s): established structure
		double max_gap_s = 1.0;  //!< hits further apart start a new run (presence must be continuous)
		double memory_s = 10.0;  //!< a cell not hit for this long is forgotten
		double max_range_m = 8.0;  //!< beam end points farther than this are not inserted
	};

	CStaticEvidenceGrid() : CStaticEvidenceGrid(TOptions()) {}
	explicit CStaticEvidenceGrid(const TOptions& options) : m_options(options) {}

	/** Adds the end points of the valid beams of `scan` (robot at `robotPose`
	 * in the world, time t_s), except those flagged in `skip` (optional). */
	void insert(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose, double t_s,
				const std::vector<bool>* skip = nullptr);
	/** Earliest time at which a cell within radius_m of `p` (world), still
	 * in memory at t_s, became established; +infinity if none: `p` is not on
	 * static structure. */
	double staticSince(const mrpt::math::TPoint2D& p, double t_s) const;

	size_t cells() const { return m_cells.size(); }
	const TOptions& options() const { return m_options; }

   private:
	struct TCell
	{
		double run_start_s = 0, last_s = 0;  //!< current run of hits (gaps <= max_gap_s)
		int scans = 0;  //!< distinct scans in the current run
		double established_s = std::numeric_limits<double>::infinity();  //!< when it became established
	};
	int64_t keyOf(int ix, int iy) const { return common::cellKey(ix, iy); }
	int index(double v) const;
	void hit(int64_t key, double t_s);
	void prune(double t_s);

	TOptions m_options;
	std::unordered_map<int64_t, TCell> m_cells;
	double m_lastPrune_s = -std::numeric_limits<double>::infinity();
};

}  // namespace hslam::dynamic
