#include <hslam/common/options_io.h>
#include <hslam/common/range_data.h>
#include <hslam/maps/CTiledOccupancyGridMap2D.h>
#include <hslam/maps/grid_rendering.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/initializer.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <sstream>

using namespace hslam::maps;

IMPLEMENTS_SERIALIZABLE(CTiledOccupancyGridMap2D, mrpt::maps::CMetricMap, hslam::maps)
MAP_DEFINITION_REGISTER("hslam::maps::CTiledOccupancyGridMap2D,tiledOccupancyGrid", hslam::maps::CTiledOccupancyGridMap2D)

MRPT_INITIALIZER(hslam_register_tiled_map) { mrpt::rtti::registerClass(CLASS_ID(hslam::maps::CTiledOccupancyGridMap2D)); }

namespace hslam::maps
{
void registerTiledMapClasses()
{
	// Touching the registry id keeps this translation unit (and its static
	// registration) in any program that links hslam::maps statically.
	static_cast<void>(CTiledOccupancyGridMap2D::m_private_map_register_id);
	mrpt::rtti::registerClass(CLASS_ID(CTiledOccupancyGridMap2D));
}

namespace
{
/** Forwards every field to another visitor with a key prefix ("laser_"...),
 * so two option structs with the same key names can share one INI section. */
template <class V>
struct TPrefixedVisitor
{
	V& v;
	std::string prefix;
	void real(const std::string& k, double& x, double a, double b) { v.real(prefix + k, x, a, b); }
	void integer(const std::string& k, int& x, int a, int b) { v.integer(prefix + k, x, a, b); }
	void flag(const std::string& k, bool& x) { v.flag(prefix + k, x); }
	void choice(const std::string& k, std::string& x, const std::vector<std::string>& a) { v.choice(prefix + k, x, a); }
	void degrees(const std::string& k, double& x, double a, double b) { v.degrees(prefix + k, x, a, b); }
	void text(const std::string& k, std::string& x) { v.text(prefix + k, x); }
};

template <class V>
void visitInsertion(CTiledOccupancyGridMap2D::TInsertionOptions& o, V& v)
{
	TPrefixedVisitor<V> laser{v, "laser_"}, sonar{v, "sonar_"};
	o.laser.visit(laser);
	o.sonar.visit(sonar);
}

const char* kCreation = "creationOpts";
const char* kInsert = "insertOpts";
const char* kLikelihood = "likelihoodOpts";
}  // namespace

void loadTiledMapOptions(CTiledOccupancyGrid::TOptions& grid, CTiledOccupancyGridMap2D::TInsertionOptions& ins,
						 CTiledOccupancyGridMap2D::TLikelihoodOptions& lik, const mrpt::config::CConfigFileBase& cfg,
						 const std::string& creationSection, const std::string& insertSection,
						 const std::string& likelihoodSection)
{
	{
		// MRPT's generic map keys (enableSaveAs3DObject, ...) share this
		// section, so unknown keys are not rejected here.
		common::CSectionReader reader(cfg, creationSection);
		grid.visit(reader);
	}
	{
		common::CSectionReader reader(cfg, insertSection);
		visitInsertion(ins, reader);
		reader.checkNoUnknownKeys();
	}
	common::loadOptions(lik, cfg, likelihoodSection);
}

// ---------------------------------------------------------------- definition
CTiledOccupancyGridMap2D::TMapDefinition::TMapDefinition() = default;

void CTiledOccupancyGridMap2D::TMapDefinition::loadFromConfigFile_map_specific(
	const mrpt::config::CConfigFileBase& source, const std::string& prefix)
{
	loadTiledMapOptions(gridOpts, insertionOpts, likelihoodOpts, source, prefix + "_" + kCreation,
						prefix + "_" + kInsert, prefix + "_" + kLikelihood);
}

void CTiledOccupancyGridMap2D::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const
{
	CTiledOccupancyGridMap2D tmp(gridOpts);
	tmp.insertionOptions = insertionOpts;
	tmp.likelihoodOptions = likelihoodOpts;
	out << tmp.optionsAsIni();
}

mrpt::maps::CMetricMap* CTiledOccupancyGridMap2D::internal_CreateFromMapDefinition(
	const mrpt::maps::TMetricMapInitializer& def_)
{
	const auto& def = dynamic_cast<const TMapDefinition&>(def_);
	auto* map = new CTiledOccupancyGridMap2D(def.gridOpts);
	map->insertionOptions = def.insertionOpts;
	map->likelihoodOptions = def.likelihoodOpts;
	return map;
}

// ---------------------------------------------------------------- map
CTiledOccupancyGridMap2D::CTiledOccupancyGridMap2D(const CTiledOccupancyGrid::TOptions& gridOptions)
	: m_grid(gridOptions)
{
}

std::string CTiledOccupancyGridMap2D::optionsAsIni() const
{
	mrpt::config::CConfigFileMemory cfg;
	common::saveOptions(m_grid.options(), cfg, kCreation);
	TInsertionOptions ins = insertionOptions;
	common::CSectionWriter writer(cfg, kInsert);
	visitInsertion(ins, writer);
	common::saveOptions(likelihoodOptions, cfg, kLikelihood);
	return cfg.getContent();
}

mrpt::maps::COccupancyGridMap2D CTiledOccupancyGridMap2D::getAsMrptGrid(int marginCells) const
{
	TCellBounds b = m_grid.observedBounds();
	if (b.empty()) b = {-1, 0, -1, 0};
	b.gxMin -= marginCells, b.gyMin -= marginCells, b.gxMax += marginCells, b.gyMax += marginCells;
	return toMrptGrid(m_grid, b);
}

bool CTiledOccupancyGridMap2D::isEmpty() const { return m_grid.tileCount() == 0; }

void CTiledOccupancyGridMap2D::saveMetricMapRepresentationToFile(const std::string& prefix) const
{
	renderGrid(m_grid, frameForObservedArea(m_grid, 10, 1)).saveToFile(prefix + "_tiled_grid.png");
}

void CTiledOccupancyGridMap2D::getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const
{
	if (!genericMapParams.enableSaveAs3DObject || isEmpty()) return;
	getAsMrptGrid().getVisualizationInto(outObj);
}

std::string CTiledOccupancyGridMap2D::asString() const
{
	std::ostringstream s;
	s << "hslam::maps::CTiledOccupancyGridMap2D: " << m_grid.tileCount() << " tiles of "
	  << m_grid.options().tile_size_cells << "x" << m_grid.options().tile_size_cells << " cells at "
	  << m_grid.options().resolution_m << " m, " << m_grid.memoryBytes() << " bytes";
	return s.str();
}

void CTiledOccupancyGridMap2D::internal_clear() { m_grid.clear(); }

bool CTiledOccupancyGridMap2D::internal_insertObservation(const mrpt::obs::CObservation& obs,
														  const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	const mrpt::poses::CPose2D pose = robotPose ? mrpt::poses::CPose2D(*robotPose) : mrpt::poses::CPose2D();
	if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs))
	{
		CLaserGridInserter inserter(insertionOptions.laser);
		const auto s = inserter.insert(m_grid, pose, *scan);
		return s.cells_updated > 0;
	}
	if (const auto* range = dynamic_cast<const mrpt::obs::CObservationRange*>(&obs))
	{
		const CSonarGridInserter inserter(insertionOptions.sonar);
		return inserter.insert(m_grid, pose, *range).cells_updated > 0;
	}
	return false;
}

bool CTiledOccupancyGridMap2D::internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const
{
	return dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs) != nullptr;
}

double CTiledOccupancyGridMap2D::distanceToNearestObstacle(double x, double y) const
{
	const CTiledGridGeometry& geo = m_grid.geometry();
	const double maxD = likelihoodOptions.max_corr_distance_m;
	const int k = static_cast<int>(std::ceil(maxD / geo.resolution_m()));
	const float threshold = probabilityToLogOdds(likelihoodOptions.occupied_threshold);
	const TGlobalCell c = geo.cellOf(x, y);
	double best2 = maxD * maxD;
	for (int dy = -k; dy <= k; ++dy)
		for (int dx = -k; dx <= k; ++dx)
		{
			const TGlobalCell g{c.gx + dx, c.gy + dy};
			if (m_grid.logOdds(g) <= threshold) continue;
			const auto p = geo.cellCentre(g);
			best2 = std::min(best2, (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y));
		}
	return std::sqrt(best2);
}

double CTiledOccupancyGridMap2D::internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
																	   const mrpt::poses::CPose3D& takenFrom) const
{
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan) return 0.0;
	const common::TScanMount mount = common::scanMount(scan->sensorPose);
	const mrpt::poses::CPose2D sensor = mrpt::poses::CPose2D(takenFrom) + mount.pose();
	const double c = std::cos(sensor.phi()), s = std::sin(sensor.phi());
	const double inv2s2 = 0.5 / (likelihoodOptions.sigma_m * likelihoodOptions.sigma_m);
	const size_t n = scan->getScanSize();
	double logLik = 0;
	for (size_t i = 0; i < n; i += static_cast<size_t>(likelihoodOptions.decimation))
	{
		const double r = scan->getScanRange(i);
		if (!scan->getScanRangeValidity(i) || !std::isfinite(r) || r <= 0 || r > likelihoodOptions.max_range_m) continue;
		const double a = scan->getScanAngle(i);
		const double lx = r * std::cos(a), ly = mount.sineSign() * r * std::sin(a);
		const double d = distanceToNearestObstacle(sensor.x() + c * lx - s * ly, sensor.y() + s * lx + c * ly);
		logLik += std::log(likelihoodOptions.z_hit * std::exp(-d * d * inv2s2) + likelihoodOptions.z_random);
	}
	return logLik;
}

// ---------------------------------------------------------------- serialisation
uint8_t CTiledOccupancyGridMap2D::serializeGetVersion() const { return 0; }

void CTiledOccupancyGridMap2D::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << genericMapParams << optionsAsIni();
	const int n = m_grid.options().tile_size_cells;
	out.WriteAs<uint32_t>(m_grid.tileCount());
	for (const TTileIndex& t : m_grid.tilesInCreationOrder())
	{
		out.WriteAs<int32_t>(t.ix);
		out.WriteAs<int32_t>(t.iy);
		out.WriteBufferFixEndianness(m_grid.findTile(t)->data(), static_cast<size_t>(n) * n);
	}
}

void CTiledOccupancyGridMap2D::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	in >> genericMapParams;
	// The INI text's length is checked before allocating (a corrupt length
	// would make MRPT's string reader allocate up to 4 GB; issue 15).
	const auto iniChars = in.ReadAs<uint32_t>();
	if (iniChars > (1u << 20)) THROW_EXCEPTION_FMT("CTiledOccupancyGridMap2D: options text of %u bytes (> 1 MiB)", iniChars);
	std::string ini(iniChars, '\0');
	in.ReadBuffer(ini.data(), iniChars);
	mrpt::config::CConfigFileMemory cfg(ini);
	CTiledOccupancyGrid::TOptions gridOpts;
	loadTiledMapOptions(gridOpts, insertionOptions, likelihoodOptions, cfg, kCreation, kInsert, kLikelihood);
	m_grid = CTiledOccupancyGrid(gridOpts);
	const int n = gridOpts.tile_size_cells;
	const auto tiles = in.ReadAs<uint32_t>();
	for (uint32_t i = 0; i < tiles; ++i)
	{
		TTileIndex t;
		t.ix = in.ReadAs<int32_t>();
		t.iy = in.ReadAs<int32_t>();
		in.ReadBufferFixEndianness(m_grid.tileForWriting(t).data(), static_cast<size_t>(n) * n);
	}
}

}  // namespace hslam::maps
