/* hslam: the laser scans of a run, kept compactly so the map can be rebuilt
 * from the optimised graph (issue 13, part 4: "map from the optimised graph";
 * DESIGN.md figure 55: "tiles re-rendered where poses moved").
 *
 * Per scan: ranges (float), validity and what the dynamic-mapping stage gave
 * the grid with it (TDynamicMapUpdate: the filter's excluded-beam mask, so
 * people never become occupied cells, also after re-rendering, and the late
 * exclusions emitted at that scan, as beams of earlier scans). The scan
 * geometry (aperture, direction, sensor pose, maximum range) is shared by all
 * scans of one sensor: one prototype observation per geometry, not one per
 * scan (~1 KB per scan of 181 beams instead of a full CObservation2DRangeScan).
 *
 * replay() runs the pipeline's own insertion path (CDynamicMappingStage
 * without a filter: late exclusions first, then the scan) with each scan at a
 * given pose; a late exclusion takes back the hit its beam made in the
 * re-rendered map, wherever the new poses put it. */
#pragma once

#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <hslam/slam/CRetroClearedGrid.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::slam
{
class CScanArchive
{
   public:
	/** Stores `scan` with what the grid received with it online. Every
	 * scan of the run must be added (late exclusions count scans back). */
	void add(const mrpt::obs::CObservation2DRangeScan& scan, const TDynamicMapUpdate& update);

	/** Inserts every stored scan into `grid` with the robot at poses[i]
	 * (poses.size() == size()), through `inserter`. */
	void replay(maps::CTiledOccupancyGrid& grid, const std::vector<mrpt::poses::CPose2D>& poses,
				maps::CLaserGridInserter& inserter) const;

	size_t size() const { return m_scans.size(); }
	size_t memoryBytes() const;

   private:
	struct TStoredScan
	{
		uint16_t geometry = 0;  //!< index into m_prototypes
		std::vector<float> range_m;
		std::vector<bool> valid;
		TDynamicMapUpdate update;
	};
	uint16_t geometryOf(const mrpt::obs::CObservation2DRangeScan& scan);
	void restore(const TStoredScan& s, mrpt::obs::CObservation2DRangeScan& scan) const;

	std::vector<mrpt::obs::CObservation2DRangeScan> m_prototypes;  //!< one per scan geometry
	std::vector<TStoredScan> m_scans;
};

}  // namespace hslam::slam
