/* hslam: the laser scans of a run, kept compactly so the map can be rebuilt
 * from the optimised graph (issue 13, part 4: "map from the optimised graph";
 * DESIGN.md figure 55: "tiles re-rendered where poses moved").
 *
 * Per scan: ranges (float), validity, the dynamic filter's excluded-beam mask
 * (people never become occupied cells, also after re-rendering) and the late
 * exclusions the filter emitted at that scan (retro_clear_world, stored in the
 * robot frame of that scan so they move with it). The scan geometry (aperture,
 * direction, sensor pose, maximum range) is shared by all scans of one sensor:
 * one prototype observation per geometry, not one per scan (~1 KB per scan of
 * 181 beams instead of a full CObservation2DRangeScan).
 *
 * replay() runs the pipeline's own insertion path (maps::CLaserGridInserter
 * and dynamic::undoOccupiedHits, in the pipeline's order: late exclusions
 * first, then the scan) with each scan at a given pose. */
#pragma once

#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::slam
{
class CScanArchive
{
   public:
	/** Stores `scan` taken at `onlinePose` with its excluded beams (may be
	 * null) and the late exclusions (world frame at `onlinePose`) emitted
	 * just before it was inserted. */
	void add(const mrpt::obs::CObservation2DRangeScan& scan, const std::vector<bool>* excludedBeams,
			 const std::vector<mrpt::math::TPoint2D>& retroClearWorld, const mrpt::poses::CPose2D& onlinePose);

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
		std::vector<bool> valid, excluded;  //!< excluded empty = none
		std::vector<mrpt::math::TPoint2Df> retro_clear_robot;  //!< late exclusions, robot frame
	};
	uint16_t geometryOf(const mrpt::obs::CObservation2DRangeScan& scan);
	void restore(const TStoredScan& s, mrpt::obs::CObservation2DRangeScan& scan) const;

	std::vector<mrpt::obs::CObservation2DRangeScan> m_prototypes;  //!< one per scan geometry
	std::vector<TStoredScan> m_scans;
};

}  // namespace hslam::slam
