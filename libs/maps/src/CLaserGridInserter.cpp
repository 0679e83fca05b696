#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/common/range_data.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace hslam::maps
{
CLaserGridInserter::CLaserGridInserter(const TOptions& options)
	: m_options(options),
	  m_freeLogOdds(probabilityToLogOdds(options.free_probability)),
	  m_occupiedLogOdds(probabilityToLogOdds(options.occupied_probability))
{
}

TLaserInsertStats CLaserGridInserter::insert(CTiledOccupancyGrid& grid, const mrpt::poses::CPose2D& robotPose,
											 const mrpt::obs::CObservation2DRangeScan& scan,
											 const std::vector<bool>* hitIsExcluded, TLaserInsertionRecord* record)
{
	TLaserInsertStats stats;
	const common::TScanMount mount = common::scanMount(scan.sensorPose);
	const mrpt::poses::CPose2D sensor = robotPose + mount.pose();
	const auto& dirs = m_sinCos.getSinCosForScan(scan);
	const CTiledGridGeometry& geo = grid.geometry();
	const TGlobalCell origin = geo.cellOf(sensor.x(), sensor.y());
	const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());

	const size_t beams = scan.getScanSize();
	const float* ranges = beams ? &scan.getScanRange(0) : nullptr;  // contiguous; avoids a call per beam
	for (size_t i = 0; i < beams; ++i)
	{
		double range = ranges[i];
		if (!scan.getScanRangeValidity(i) || !std::isfinite(range) || range <= 0)
		{
			++stats.beams_skipped;
			continue;
		}
		bool hit = true;
		if (range > m_options.max_range_m)
		{
			if (!m_options.insert_free_beyond_range)
			{
				++stats.beams_skipped;
				continue;
			}
			range = m_options.max_range_m;
			hit = false;
		}
		if (hit && hitIsExcluded && i < hitIsExcluded->size() && (*hitIsExcluded)[i]) hit = false;

		// Beam end point: sensor frame -> world frame.
		const double lx = range * dirs.ccos[i], ly = mount.sineSign() * range * dirs.csin[i];
		const TGlobalCell end = geo.cellOf(sensor.x() + c * lx - s * ly, sensor.y() + s * lx + c * ly);
		const TLogOddsCell before = (record && hit) ? grid.rawCell(end) : kUnknownCell;
		stats.cells_updated += grid.updateRay(origin, end, m_freeLogOdds, hit ? m_occupiedLogOdds : m_freeLogOdds);
		if (record && hit)
			record->hits.push_back({i, end, before, grid.rawCell(end) - (before == kUnknownCell ? 0 : before)});
		if (hit)
			++stats.beams_hit;
		else
			++stats.beams_free_only;
	}
	return stats;
}

size_t CLaserGridInserter::undo(CTiledOccupancyGrid& grid, const TLaserInsertionRecord& record,
								const std::vector<size_t>& beams)
{
	size_t undone = 0;
	for (auto it = record.hits.rbegin(); it != record.hits.rend(); ++it)
	{
		if (std::find(beams.begin(), beams.end(), it->beam) == beams.end()) continue;
		const int after = (it->before == kUnknownCell ? 0 : it->before) + it->applied;
		const TLogOddsCell now = grid.rawCell(it->cell);
		// Unchanged since the hit (a later update of a saturated cell may have
		// applied 0 unseen, hence not at the clamp): back to the value before,
		// bit for bit, unknown included. Else subtract what the hit applied.
		if (now == after && std::abs(after) < grid.clampCellUnits())
			grid.setRawCell(it->cell, it->before);
		else
		{
			TLogOddsCell v = now;
			CTile::add(v, -it->applied, grid.clampCellUnits());
			grid.setRawCell(it->cell, v);
		}
		++undone;
	}
	return undone;
}

}  // namespace hslam::maps
