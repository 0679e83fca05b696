#include <hslam/slam/CSonarMappingStage.h>

namespace hslam::slam
{
namespace
{
maps::CSonarGridInserter::TOptions withUnitWeight(maps::CSonarGridInserter::TOptions o)
{
	o.weight = 1.0;
	return o;
}
}  // namespace

CSonarMappingStage::CSonarMappingStage(const TSonarMappingOptions& mapping, const TTbfStageOptions& tbf)
	: m_mapping(mapping),
	  m_tbf(tbf),
	  m_inserter(mapping.model),
	  m_sonarOnlyInserter(withUnitWeight(mapping.model)),
	  m_tbfDetector(tbf.detector)
{
}

void CSonarMappingStage::keepSonarOnlyMap(const maps::CTiledOccupancyGrid::TOptions& gridOptions)
{
	m_sonarOnly = std::make_unique<maps::CTiledOccupancyGrid>(gridOptions);
}

void CSonarMappingStage::process(const mrpt::obs::CObservationRange& obs, const mrpt::poses::CPose2D& robotPose,
								 maps::CTiledOccupancyGrid& grid, common::CStageTimer& timer)
{
	++m_counters.observations;
	if (m_mapping.enabled)
	{
		common::CStageTimer::CScope t(timer, "sonar_update");
		const maps::TSonarInsertStats stats = m_inserter.insert(grid, robotPose, obs);
		m_counters.readings_inserted += stats.readings_inserted;
		m_counters.readings_skipped += stats.readings_skipped;
	}
	if (m_sonarOnly)
	{
		// Not timed as part of the mapping: a by-product for the images.
		m_sonarOnlyInserter.insert(*m_sonarOnly, robotPose, obs);
	}
	if (m_tbf.enabled)
	{
		common::CStageTimer::CScope t(timer, "sonar_corners");
		if (m_tbfDetector.process(robotPose, obs)) ++m_counters.tbf_columns;
	}
}

std::vector<sonar::TTbfCorner> CSonarMappingStage::corners() const
{
	if (!m_tbf.enabled) return {};
	return m_tbfDetector.corners(m_tbf.min_support);
}

}  // namespace hslam::slam
