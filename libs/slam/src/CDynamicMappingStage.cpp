#include <hslam/slam/CDynamicMappingStage.h>

#include <stdexcept>

namespace hslam::slam
{
TDynamicMapUpdate dynamicMapUpdate(const dynamic::TDynamicFrame& frame)
{
	TDynamicMapUpdate u;
	u.excluded = frame.beam_is_dynamic;
	for (const auto& r : frame.retro_clear_beams)
		if (r.scan < frame.scan_index)
			u.retro_clear.push_back({static_cast<uint32_t>(frame.scan_index - r.scan), static_cast<uint32_t>(r.beam)});
	if (frame.pending_since_scan <= frame.scan_index)
		u.keep_scans = static_cast<uint32_t>(frame.scan_index + 1 - frame.pending_since_scan);
	return u;
}

CDynamicMappingStage::CDynamicMappingStage(maps::CLaserGridInserter& inserter,
										   std::unique_ptr<dynamic::CDynamicObjectFilter> filter)
	: m_inserter(&inserter), m_filter(std::move(filter))
{
}

size_t CDynamicMappingStage::addGrid(maps::CTiledOccupancyGrid& grid)
{
	m_grids.emplace_back(grid);
	return m_grids.size() - 1;
}

const TDynamicMapUpdate& CDynamicMappingStage::filterScan(const mrpt::obs::CObservation2DRangeScan& scan,
														  const mrpt::poses::CPose2D& robotPose, double t_s)
{
	m_update = m_filter ? dynamicMapUpdate(m_filter->process(scan, robotPose, t_s)) : TDynamicMapUpdate();
	return m_update;
}

maps::TLaserInsertStats CDynamicMappingStage::insertScan(size_t grid, const mrpt::obs::CObservation2DRangeScan& scan,
														 const mrpt::poses::CPose2D& robotPose,
														 const TDynamicMapUpdate& update)
{
	if (grid >= m_grids.size()) throw std::out_of_range("CDynamicMappingStage::insertScan: no such grid");
	return m_grids[grid].insert(*m_inserter, scan, robotPose, update);
}

const TDynamicMapUpdate& CDynamicMappingStage::process(const mrpt::obs::CObservation2DRangeScan& scan,
													   const mrpt::poses::CPose2D& robotPose, double t_s)
{
	filterScan(scan, robotPose, t_s);
	for (size_t g = 0; g < m_grids.size(); ++g) insertScan(g, scan, robotPose, m_update);
	return m_update;
}

}  // namespace hslam::slam
