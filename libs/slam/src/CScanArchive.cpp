#include <hslam/slam/CDynamicMappingStage.h>
#include <hslam/slam/CScanArchive.h>

#include <stdexcept>

namespace hslam::slam
{
namespace
{
bool sameGeometry(const mrpt::obs::CObservation2DRangeScan& a, const mrpt::obs::CObservation2DRangeScan& b)
{
	return a.getScanSize() == b.getScanSize() && a.aperture == b.aperture && a.rightToLeft == b.rightToLeft &&
		   a.maxRange == b.maxRange && a.sensorPose == b.sensorPose && a.sensorLabel == b.sensorLabel;
}
}  // namespace

uint16_t CScanArchive::geometryOf(const mrpt::obs::CObservation2DRangeScan& scan)
{
	for (size_t i = 0; i < m_prototypes.size(); ++i)
		if (sameGeometry(m_prototypes[i], scan)) return static_cast<uint16_t>(i);
	if (m_prototypes.size() >= 0xFFFF) throw std::runtime_error("CScanArchive: too many scan geometries");
	m_prototypes.push_back(scan);
	return static_cast<uint16_t>(m_prototypes.size() - 1);
}

void CScanArchive::add(const mrpt::obs::CObservation2DRangeScan& scan, const TDynamicMapUpdate& update)
{
	TStoredScan s;
	s.geometry = geometryOf(scan);
	const size_t n = scan.getScanSize();
	s.range_m.resize(n);
	s.valid.resize(n);
	for (size_t i = 0; i < n; ++i) s.range_m[i] = scan.getScanRange(i), s.valid[i] = scan.getScanRangeValidity(i);
	s.update = update;
	m_scans.push_back(std::move(s));
}

void CScanArchive::restore(const TStoredScan& s, mrpt::obs::CObservation2DRangeScan& scan) const
{
	scan = m_prototypes[s.geometry];  // geometry; ranges overwritten below
	for (size_t i = 0; i < s.range_m.size(); ++i)
	{
		scan.setScanRange(i, s.range_m[i]);
		scan.setScanRangeValidity(i, s.valid[i]);
	}
}

void CScanArchive::replay(maps::CTiledOccupancyGrid& grid, const std::vector<mrpt::poses::CPose2D>& poses,
						  maps::CLaserGridInserter& inserter) const
{
	if (poses.size() != m_scans.size()) throw std::invalid_argument("CScanArchive::replay: one pose per scan needed");
	CDynamicMappingStage stage(inserter);  // no filter: the stored updates
	stage.addGrid(grid);
	mrpt::obs::CObservation2DRangeScan scan;
	for (size_t k = 0; k < m_scans.size(); ++k)
	{
		restore(m_scans[k], scan);
		stage.insertScan(0, scan, poses[k], m_scans[k].update);
	}
}

size_t CScanArchive::memoryBytes() const
{
	size_t bytes = m_scans.capacity() * sizeof(TStoredScan);
	for (const auto& s : m_scans)
		bytes += s.range_m.capacity() * sizeof(float) + (s.valid.capacity() + s.update.excluded.capacity()) / 8 +
				 s.update.retro_clear.capacity() * sizeof(TRetroClear);
	return bytes;
}

}  // namespace hslam::slam
