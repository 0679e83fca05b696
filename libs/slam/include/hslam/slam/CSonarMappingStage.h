/* hslam: the sonar stage of the mapping pipeline (thesis figure 55, 4.3 and
 * 4.6.2 iii-iv): every sonar ring observation (CObservationRange) is
 *   1. inserted into the grid with the sonar inverse model (CSonarGridInserter,
 *      fast or standard model, log-odds weighted against the laser: 4.6.2 ii);
 *   2. fed to the TBF corner detector (CTbfCornerDetector, 4.3), which yields
 *      sonar corners with support counts and covariance.
 * The caller gives the robot pose of the reading (CMappingPipeline: the pose
 * estimated at the latest laser scan composed with the odometry since then).
 *
 * Optionally (keepSensorMaps) a sonar-only grid is kept as well, inserted with
 * weight 1 so that the sonar evidence is readable on its own (thesis figures
 * 135-141 show sonar-only maps).
 *
 * INI: [sonar_model] = `enabled` + CSonarGridInserter::TOptions,
 *      [tbf] = `enabled`, `min_support` + CTbfCornerDetector::TOptions.
 * No file I/O (batch_outputs.h writes the corners and images). */
#pragma once

#include <hslam/common/CStageTimer.h>
#include <hslam/maps/CSonarGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <hslam/sonar/CTbfCornerDetector.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <vector>

namespace hslam::slam
{
/** [sonar_model]: the pipeline's switch plus the inverse model options. */
struct TSonarMappingOptions
{
	bool enabled = false;  //!< insert sonar readings into the map (see hslam-default.ini for why off)
	maps::CSonarGridInserter::TOptions model;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		model.visit(v);
	}
};

/** [tbf]: the pipeline's switch, the output filter and the detector options. */
struct TTbfStageOptions
{
	bool enabled = true;  //!< run TBF on the sonar stream (sonar_corners.csv)
	int min_support = 4;  //!< corners with less support are not reported (hslam-bench sonar)
	sonar::CTbfCornerDetector::TOptions detector;

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.integer("min_support", min_support, 1, 1000000);
		detector.visit(v);
	}
};

struct TSonarStageCounters
{
	size_t observations = 0;  //!< ring observations processed
	size_t readings_inserted = 0;  //!< single sonar readings put into the grid
	size_t readings_skipped = 0;  //!< no echo, NaN or beyond the range limit
	size_t tbf_columns = 0;  //!< observations that became a TBF window column
};

class CSonarMappingStage
{
   public:
	CSonarMappingStage(const TSonarMappingOptions& mapping, const TTbfStageOptions& tbf);

	/** True if the stage does anything (grid insertion or TBF). */
	bool active() const { return m_mapping.enabled || m_tbf.enabled; }

	/** Processes one ring observation taken at `robotPose`: grid update
	 * (stage "sonar_update") and TBF (stage "sonar_corners"). */
	void process(const mrpt::obs::CObservationRange& obs, const mrpt::poses::CPose2D& robotPose,
				 maps::CTiledOccupancyGrid& grid, common::CStageTimer& timer);

	/** Also keep a grid built from the sonars alone (weight 1). */
	void keepSonarOnlyMap(const maps::CTiledOccupancyGrid::TOptions& gridOptions);
	/** The sonar-only grid, or null if not kept. */
	const maps::CTiledOccupancyGrid* sonarOnlyMap() const { return m_sonarOnly.get(); }

	/** Whether any sonar ring was processed (a laser-only log has none). */
	bool sawSonar() const { return m_counters.observations > 0; }
	/** Whether the run reports TBF corners: TBF on and the log had sonar
	 * (sonar_corners.csv, map_sonar_corners.png, the report's section). */
	bool reportsCorners() const { return m_tbf.enabled && sawSonar(); }
	/** TBF corners with support >= [tbf] min_support (empty if TBF is off). */
	std::vector<sonar::TTbfCorner> corners() const;

	const TSonarMappingOptions& mappingOptions() const { return m_mapping; }
	const TTbfStageOptions& tbfOptions() const { return m_tbf; }
	const TSonarStageCounters& counters() const { return m_counters; }

   private:
	TSonarMappingOptions m_mapping;
	TTbfStageOptions m_tbf;
	maps::CSonarGridInserter m_inserter;
	maps::CSonarGridInserter m_sonarOnlyInserter;  //!< same model, weight 1
	std::unique_ptr<maps::CTiledOccupancyGrid> m_sonarOnly;
	sonar::CTbfCornerDetector m_tbfDetector;
	TSonarStageCounters m_counters;
};

}  // namespace hslam::slam
