#include <hslam/maps/CSonarGridInserter.h>
#include <hslam/maps/grid_ray_tracing.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hslam::maps
{
namespace
{
/** Distance and angle from the beam axis of a cell centre. */
struct TCellPolar
{
	double d = 0, alpha = 0;
};

TCellPolar polarOf(const mrpt::math::TPoint2D& p, const mrpt::math::TPose2D& sensor)
{
	const double dx = p.x - sensor.x, dy = p.y - sensor.y;
	TCellPolar out;
	out.d = std::hypot(dx, dy);
	out.alpha = out.d > 1e-9 ? mrpt::math::wrapToPi(std::atan2(dy, dx) - sensor.phi) : 0.0;
	return out;
}
}  // namespace

CSonarGridInserter::CSonarGridInserter(const TOptions& options) : m_options(options), m_fast(options.model == "fast")
{
	if (options.model != "fast" && options.model != "standard")
		throw std::invalid_argument("CSonarGridInserter: model must be 'fast' or 'standard', got '" + options.model + "'");
}

double CSonarGridInserter::cellProbability(double d, double alpha, const TSonarReading& r, bool region1) const
{
	const double R = r.sensor_max_range_m > 0 ? r.sensor_max_range_m : m_options.max_range_m;
	const double beta = 0.5 * r.cone_aperture_rad;
	// eq. 86-87: confidence from the distance and the angle off the axis.
	const double s = std::clamp(0.5 * ((R - d) / R + (beta - std::abs(alpha)) / beta), 0.0, 1.0);
	const double amplitude = m_options.max_occupied_probability - 0.5;  // see the header: correct side of 0.5
	return region1 ? 0.5 + amplitude * s : 0.5 - amplitude * s;
}

float CSonarGridInserter::cellLogOdds(double d, double alpha, const TSonarReading& r, bool region1) const
{
	return static_cast<float>(m_options.weight) * probabilityToLogOdds(cellProbability(d, alpha, r, region1));
}

TSonarInsertStats CSonarGridInserter::insert(CTiledOccupancyGrid& grid, const TSonarReading& reading) const
{
	TSonarInsertStats stats;
	TSonarReading r = reading;
	if (!(r.cone_aperture_rad > 0)) r.cone_aperture_rad = m_options.default_cone_aperture_rad;
	double range = r.range_m;
	bool withArc = true;
	if (!std::isfinite(range) || range <= 0)
	{
		++stats.readings_skipped;
		return stats;
	}
	if (range > m_options.max_range_m)
	{
		if (!m_options.insert_free_beyond_range)
		{
			++stats.readings_skipped;
			return stats;
		}
		range = m_options.max_range_m;
		withArc = false;
	}
	stats.cells_updated = m_fast ? insertFast(grid, r, range, withArc) : insertStandard(grid, r, range, withArc);
	++stats.readings_inserted;
	return stats;
}

TSonarInsertStats CSonarGridInserter::insert(CTiledOccupancyGrid& grid, const mrpt::poses::CPose2D& robotPose,
											 const mrpt::obs::CObservationRange& obs) const
{
	TSonarInsertStats total;
	for (const auto& m : obs.sensedData)
	{
		const mrpt::poses::CPose2D onRobot(m.sensorPose.x, m.sensorPose.y, m.sensorPose.yaw);
		TSonarReading r;
		r.sensor = (robotPose + onRobot).asTPose();
		r.range_m = m.sensedDistance;
		r.cone_aperture_rad = obs.sensorConeApperture;
		r.sensor_max_range_m = obs.maxSensorDistance;
		if (m.sensedDistance < obs.minSensorDistance) r.range_m = 0;  // below the blind zone: no information
		const TSonarInsertStats s = insert(grid, r);
		total.readings_inserted += s.readings_inserted;
		total.readings_skipped += s.readings_skipped;
		total.cells_updated += s.cells_updated;
	}
	return total;
}

size_t CSonarGridInserter::insertFast(CTiledOccupancyGrid& grid, const TSonarReading& r, double range,
									  bool withArc) const
{
	const CTiledGridGeometry& geo = grid.geometry();
	const double res = geo.resolution_m();
	const double c = std::cos(r.sensor.phi), s = std::sin(r.sensor.phi);
	size_t cells = 0;

	// Region 2: only the cells along the beam axis (fig. 134, blue).
	const double freeEnd = withArc ? range - m_options.arc_half_width_m : range;
	if (freeEnd > 0)
	{
		const TGlobalCell from = geo.cellOf(r.sensor.x, r.sensor.y);
		const TGlobalCell to = geo.cellOf(r.sensor.x + c * freeEnd, r.sensor.y + s * freeEnd);
		forEachCellOnSegment(from, to, [&](const TGlobalCell& g) {
			const TCellPolar p = polarOf(geo.cellCentre(g), r.sensor);
			if (p.d > freeEnd) return;
			grid.updateCell(g, cellLogOdds(p.d, p.alpha, r, false));
			++cells;
		});
	}
	if (!withArc) return cells;

	// Region 1: the arc of cells at the measured range (fig. 134, green),
	// sampled every half cell so no arc cell is skipped; each cell once.
	const double beta = 0.5 * r.cone_aperture_rad;
	const int samples = std::max(2, static_cast<int>(std::ceil(2.0 * beta * range / (0.5 * res))) + 1);
	TGlobalCell visited[3];
	int nVisited = 0;
	for (int i = 0; i < samples; ++i)
	{
		const double a = r.sensor.phi - beta + 2.0 * beta * i / (samples - 1);
		const TGlobalCell g = geo.cellOf(r.sensor.x + range * std::cos(a), r.sensor.y + range * std::sin(a));
		// Consecutive samples revisit the same cell; a digital arc can also
		// come back to a cell two or three samples later.
		if (std::find(visited, visited + nVisited, g) != visited + nVisited) continue;
		visited[2] = visited[1];
		visited[1] = visited[0];
		visited[0] = g;
		nVisited = std::min(3, nVisited + 1);
		const TCellPolar p = polarOf(geo.cellCentre(g), r.sensor);
		grid.updateCell(g, cellLogOdds(p.d, p.alpha, r, true));
		++cells;
	}
	return cells;
}

size_t CSonarGridInserter::insertStandard(CTiledOccupancyGrid& grid, const TSonarReading& r, double range,
										  bool withArc) const
{
	const CTiledGridGeometry& geo = grid.geometry();
	const double halfWidth = withArc ? m_options.arc_half_width_m : 0.0;
	const double outer = range + halfWidth;
	const double freeEnd = range - halfWidth;
	const double beta = 0.5 * r.cone_aperture_rad;

	// Bounding box of the cone sector (sensor + points along the outer arc).
	double xMin = r.sensor.x, xMax = r.sensor.x, yMin = r.sensor.y, yMax = r.sensor.y;
	for (int i = 0; i <= 16; ++i)
	{
		const double a = r.sensor.phi - beta + 2.0 * beta * i / 16.0;
		const double x = r.sensor.x + outer * std::cos(a), y = r.sensor.y + outer * std::sin(a);
		xMin = std::min(xMin, x), xMax = std::max(xMax, x), yMin = std::min(yMin, y), yMax = std::max(yMax, y);
	}
	TCellBounds box{geo.cellOf(xMin, yMin).gx, geo.cellOf(xMax, yMax).gx, geo.cellOf(xMin, yMin).gy,
					geo.cellOf(xMax, yMax).gy};
	if (m_options.standard_scans_whole_tile)  // the thesis' loop over the whole 200 x 200 map
		box.include(geo.tileBounds(geo.tileOf(geo.cellOf(r.sensor.x, r.sensor.y))));
	const TGlobalCell lo{box.gxMin, box.gyMin}, hi{box.gxMax, box.gyMax};

	// Every cell in the cone (thesis 4.6.3 pseudocode): region 1 or region 2.
	size_t cells = 0;
	for (int gy = lo.gy; gy <= hi.gy; ++gy)
		for (int gx = lo.gx; gx <= hi.gx; ++gx)
		{
			const TGlobalCell g{gx, gy};
			const TCellPolar p = polarOf(geo.cellCentre(g), r.sensor);
			if (std::abs(p.alpha) > beta || p.d > outer) continue;
			const bool region1 = withArc && std::abs(p.d - range) <= halfWidth;
			if (!region1 && p.d > freeEnd) continue;
			grid.updateCell(g, cellLogOdds(p.d, p.alpha, r, region1));
			++cells;
		}
	return cells;
}

}  // namespace hslam::maps
