/* hslam: the thesis' fast laser model for the tiled grid (4.6.2 i-ii,
 * figures 131-132, appendix G.2).
 *
 * Only the cells a beam crosses are touched: the cells between the sensor and
 * the hit get the "free" Bayes update with sensor probability 0.3 (eq. 85) and
 * the hit cell the "occupied" update. Beams longer than max_range_m (3 m in
 * the thesis, "only local readings less than 3000 mm") are not inserted, or,
 * if insert_free_beyond_range is set, only their free part up to max_range_m.
 *
 * Deviation: the thesis labels the hit cell "with a probability of 1 of being
 * full" (then limited by Max_occupied = 0.98), i.e. it overwrites the cell.
 * Here the hit is a Bayes update with occupied_probability (default 0.9): one
 * hit on an unknown cell gives 0.9, repeated hits saturate at 0.98, and a
 * spurious hit (a passing person, a mismatched pose) can still be cleared by
 * later free passes, which an overwrite to 0.98 makes needlessly slow. */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSinCosLookUpTableFor2DScans.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::maps
{
struct TLaserInsertStats
{
	size_t beams_hit = 0;  //!< beams inserted with a hit cell
	size_t beams_free_only = 0;  //!< beams beyond range inserted as free space only
	size_t beams_skipped = 0;  //!< invalid, out of range (not inserted), or masked
	size_t cells_updated = 0;
};

/** One occupied update the inserter applied: the hit cell of `beam`, its raw
 * value before the update and the delta actually applied after clamping
 * (cell units; 0 on a cell already saturated). */
struct TOccupiedHit
{
	size_t beam = 0;
	TGlobalCell cell;
	TLogOddsCell before = kUnknownCell;
	int applied = 0;
};

/** The occupied updates of one insert() call, in the order applied: what
 * CLaserGridInserter::undo needs to take a beam's hit back exactly. */
struct TLaserInsertionRecord
{
	std::vector<TOccupiedHit> hits;
};

class CLaserGridInserter
{
   public:
	struct TOptions
	{
		double free_probability = 0.3;  //!< sensor model for crossed cells (thesis 4.6.2 i, eq. 85)
		double occupied_probability = 0.9;  //!< sensor model for the hit cell (see file comment)
		double max_range_m = 3.0;  //!< longer beams are not inserted (thesis: 3000 mm)
		bool insert_free_beyond_range = false;  //!< insert the free part of longer beams up to max_range_m

		template <class V>
		void visit(V& v)
		{
			v.real("free_probability", free_probability, 0.01, 0.49);
			v.real("occupied_probability", occupied_probability, 0.51, 0.999);
			v.real("max_range_m", max_range_m, 0.1, 200.0);
			v.flag("insert_free_beyond_range", insert_free_beyond_range);
		}
	};

	CLaserGridInserter() : CLaserGridInserter(TOptions()) {}
	explicit CLaserGridInserter(const TOptions& options);

	/** Inserts one scan taken with the robot at `robotPose`. `hitIsExcluded`,
	 * if given, has one flag per beam: flagged beams (e.g. hitting a person)
	 * only clear their free part and never mark their hit cell occupied.
	 * `record`, if given, receives the occupied updates as applied. */
	TLaserInsertStats insert(CTiledOccupancyGrid& grid, const mrpt::poses::CPose2D& robotPose,
							 const mrpt::obs::CObservation2DRangeScan& scan,
							 const std::vector<bool>* hitIsExcluded = nullptr,
							 TLaserInsertionRecord* record = nullptr);

	/** Takes back the occupied updates of `record` made by the beams listed
	 * in `beams`, newest first: each cell loses exactly the delta its hit
	 * applied (0 on a cell that was saturated), clamped, so insert + undo
	 * gives back every cell's value bit for bit; a cell left below the clamp
	 * and unchanged since the hit returns to its raw value before (unknown
	 * included). Free-space updates are untouched. Returns the hits undone. */
	static size_t undo(CTiledOccupancyGrid& grid, const TLaserInsertionRecord& record,
					   const std::vector<size_t>& beams);

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
	float m_freeLogOdds, m_occupiedLogOdds;
	mrpt::obs::CSinCosLookUpTableFor2DScans m_sinCos;  //!< per-geometry cache of beam directions
};

}  // namespace hslam::maps
