/* hslam: a laser grid whose occupied hits can be taken back later, exactly
 * (issue 14; used by CDynamicMappingStage).
 *
 * Each scan is inserted with its insertion record (maps::TLaserInsertionRecord:
 * per hit beam, the cell and the log-odds delta actually applied after
 * clamping); the records of the last keep_scans scans are kept. A late
 * exclusion names a beam of an earlier scan (scans_back = 1: the scan just
 * before) and is undone with maps::CLaserGridInserter::undo, so a saturated
 * wall cell a leg beam hit loses nothing it did not gain. */
#pragma once

#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>

#include <cstdint>
#include <deque>
#include <vector>

namespace hslam::slam
{
/** A beam of an earlier scan whose occupied hit is to be taken back. */
struct TRetroClear
{
	uint32_t scans_back = 1;  //!< 1: the scan inserted just before the current one
	uint32_t beam = 0;
};

/** What a grid receives with one scan (from the dynamic filter, or stored). */
struct TDynamicMapUpdate
{
	std::vector<bool> excluded;  //!< per beam: hit not marked occupied (empty: none)
	std::vector<TRetroClear> retro_clear;  //!< late exclusions, undone before the scan is inserted
	uint32_t keep_scans = 0;  //!< insertion records later late exclusions can still reach (0: none)
};

class CRetroClearedGrid
{
   public:
	explicit CRetroClearedGrid(maps::CTiledOccupancyGrid& grid) : m_grid(&grid) {}

	/** Undoes update.retro_clear, then inserts `scan` with the robot at
	 * `robotPose` (hits of update.excluded not marked occupied). */
	maps::TLaserInsertStats insert(maps::CLaserGridInserter& inserter, const mrpt::obs::CObservation2DRangeScan& scan,
								   const mrpt::poses::CPose2D& robotPose, const TDynamicMapUpdate& update);

	maps::CTiledOccupancyGrid& grid() { return *m_grid; }
	size_t recordsKept() const { return m_history.size(); }

   private:
	/** Newest scan first: the exact inverse in the reverse order of insertion. */
	void undoLateExclusions(const std::vector<TRetroClear>& retro);

	maps::CTiledOccupancyGrid* m_grid;
	std::deque<maps::TLaserInsertionRecord> m_history;  //!< one per scan, newest last
};

}  // namespace hslam::slam
