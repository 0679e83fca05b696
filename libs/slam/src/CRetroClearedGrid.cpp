#include <hslam/slam/CRetroClearedGrid.h>

#include <map>

namespace hslam::slam
{
maps::TLaserInsertStats CRetroClearedGrid::insert(maps::CLaserGridInserter& inserter,
												  const mrpt::obs::CObservation2DRangeScan& scan,
												  const mrpt::poses::CPose2D& robotPose, const TDynamicMapUpdate& update)
{
	if (!update.retro_clear.empty()) undoLateExclusions(update.retro_clear);
	const std::vector<bool>* excluded = update.excluded.empty() ? nullptr : &update.excluded;
	if (update.keep_scans == 0)
	{
		m_history.clear();
		return inserter.insert(*m_grid, robotPose, scan, excluded);
	}
	maps::TLaserInsertionRecord record;
	const auto stats = inserter.insert(*m_grid, robotPose, scan, excluded, &record);
	m_history.push_back(std::move(record));
	while (m_history.size() > update.keep_scans) m_history.pop_front();
	return stats;
}

void CRetroClearedGrid::undoLateExclusions(const std::vector<TRetroClear>& retro)
{
	std::map<uint32_t, std::vector<size_t>> beamsByAge;  // ascending scans_back: newest scan first
	for (const auto& r : retro) beamsByAge[r.scans_back].push_back(r.beam);
	for (const auto& [back, beams] : beamsByAge)
		if (back >= 1 && back <= m_history.size())
			maps::CLaserGridInserter::undo(*m_grid, m_history[m_history.size() - back], beams);
}

}  // namespace hslam::slam
