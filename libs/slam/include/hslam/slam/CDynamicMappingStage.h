/* hslam: the one dynamic-mapping stage (issue 14; thesis 4.7: dynamic objects
 * must not be written into the map). Per laser scan:
 *     dynamic object filter (dynamic::CDynamicObjectFilter)
 *  -> late exclusions: the occupied hits of earlier beams the filter now
 *     attributes to a confirmed person are taken back exactly (retro-clear,
 *     CRetroClearedGrid: the log-odds each hit applied, after clamping)
 *  -> the scan is inserted with the filter's mask (beams on people clear
 *     their free part, never mark their hit cell occupied).
 * The same TDynamicMapUpdate re-renders a map after loop closure
 * (CScanArchive stores it per scan), and feeds any number of grids kept in
 * step (the pipeline's map and its laser-only map), each with its own
 * insertion records. Without a filter the stage just inserts. */
#pragma once

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/slam/CRetroClearedGrid.h>

#include <memory>
#include <vector>

namespace hslam::slam
{
class CDynamicMappingStage
{
   public:
	/** `inserter` (the laser model) must outlive the stage; `filter` may be null. */
	explicit CDynamicMappingStage(maps::CLaserGridInserter& inserter,
								  std::unique_ptr<dynamic::CDynamicObjectFilter> filter = nullptr);

	/** Adds a grid fed by insertScan(index); returns its index. The grid
	 * must outlive the stage. */
	size_t addGrid(maps::CTiledOccupancyGrid& grid);

	/** Runs the filter on `scan` (robot at `robotPose`, time `t_s`) and
	 * returns what every grid receives with it (nothing without a filter). */
	const TDynamicMapUpdate& filterScan(const mrpt::obs::CObservation2DRangeScan& scan,
										const mrpt::poses::CPose2D& robotPose, double t_s);

	/** Inserts `scan` into grid `grid` after the late exclusions of `update`. */
	maps::TLaserInsertStats insertScan(size_t grid, const mrpt::obs::CObservation2DRangeScan& scan,
									   const mrpt::poses::CPose2D& robotPose, const TDynamicMapUpdate& update);

	/** filterScan, then insertScan into every grid. */
	const TDynamicMapUpdate& process(const mrpt::obs::CObservation2DRangeScan& scan,
									 const mrpt::poses::CPose2D& robotPose, double t_s);

	dynamic::CDynamicObjectFilter* filter() { return m_filter.get(); }
	const dynamic::CDynamicObjectFilter* filter() const { return m_filter.get(); }
	/** The update of the latest filterScan. */
	const TDynamicMapUpdate& lastUpdate() const { return m_update; }
	size_t gridCount() const { return m_grids.size(); }

   private:
	maps::CLaserGridInserter* m_inserter;
	std::unique_ptr<dynamic::CDynamicObjectFilter> m_filter;
	std::vector<CRetroClearedGrid> m_grids;
	TDynamicMapUpdate m_update;
};

/** The grid update of one filter frame: its mask, its late exclusions as
 * scans back from the frame, and the records its pending beams still need. */
TDynamicMapUpdate dynamicMapUpdate(const dynamic::TDynamicFrame& frame);

}  // namespace hslam::slam
