/* hslam: the tiled occupancy grid (thesis 4.6.1) as a full MRPT metric map.
 *
 * hslam::maps::CTiledOccupancyGridMap2D is a mrpt::maps::CMetricMap holding a
 * CTiledOccupancyGrid (tiles created on demand: memory grows with the
 * explored area only), so it can live in a CMultiMetricMap next to MRPT's own
 * maps:
 *   - created by MRPT's map factory from an INI map-definition section, alias
 *     "tiledOccupancyGrid" (or the full class name), e.g.
 *         [MappingApplication]
 *         tiledOccupancyGrid_count = 1
 *         [MappingApplication_tiledOccupancyGrid_00_creationOpts]
 *         resolution_m = 0.1         ; + tile_size_cells, max_occupied_probability
 *         [MappingApplication_tiledOccupancyGrid_00_insertOpts]
 *         laser_max_range_m = 3.0    ; laser_* = CLaserGridInserter keys,
 *         sonar_model = fast         ; sonar_* = CSonarGridInserter keys
 *         [MappingApplication_tiledOccupancyGrid_00_likelihoodOpts]
 *         sigma_m = 0.1              ; see TLikelihoodOptions
 *     (every key documented in config_ini/tiled-map-mrpt.ini);
 *   - insertObservation: CObservation2DRangeScan with the thesis' fast laser
 *     model (CLaserGridInserter), CObservationRange with a sonar model
 *     (CSonarGridInserter, fast or standard, weighted below the laser);
 *   - computeObservationLikelihood for 2D scans: a likelihood field (Thrun,
 *     Probabilistic Robotics 6.4) evaluated on the tiles directly: each
 *     (decimated) beam end point scores z_hit N(d; 0, sigma) + z_random with d
 *     the distance to the nearest occupied cell within max_corr_distance_m;
 *   - serialisation (CSerializable, class "hslam::maps::CTiledOccupancyGridMap2D",
 *     registered with mrpt::rtti) storing the options and the raw int16 tiles,
 *     so a save/load round trip is bit-identical;
 *   - getAsMrptGrid(): the merged view as a plain COccupancyGridMap2D.
 * Registration happens at load time of the object file (MAP_DEFINITION_REGISTER
 * and an MRPT_INITIALIZER); code that links hslam::maps statically and creates
 * the map only from INI must call registerTiledMapClasses() once so the
 * linker keeps this translation unit. MRPT apps get it from the plug-in
 * module libhslam-maps-plugin.so (-p, or LD_PRELOAD for apps without -p). */
#pragma once

#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CSonarGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

namespace hslam::maps
{
/** Forces the map class registration (see the file comment). */
void registerTiledMapClasses();

class CTiledOccupancyGridMap2D : public mrpt::maps::CMetricMap
{
	DEFINE_SERIALIZABLE(CTiledOccupancyGridMap2D, hslam::maps)

   public:
	/** Insertion options: one set per sensor model. */
	struct TInsertionOptions
	{
		CLaserGridInserter::TOptions laser;
		CSonarGridInserter::TOptions sonar;
	};

	/** Likelihood field for 2D scans. */
	struct TLikelihoodOptions
	{
		double sigma_m = 0.1;  //!< std. dev. of the hit distance (m)
		double max_corr_distance_m = 0.3;  //!< search radius for the nearest occupied cell (m)
		double z_hit = 0.9;  //!< weight of the Gaussian term
		double z_random = 0.1;  //!< weight of the uniform term
		double occupied_threshold = 0.6;  //!< cells with p_occ above are obstacles
		double max_range_m = 8.0;  //!< beams longer than this are ignored (m)
		int decimation = 4;  //!< use every n-th beam

		template <class V>
		void visit(V& v)
		{
			v.real("sigma_m", sigma_m, 0.001, 5.0);
			v.real("max_corr_distance_m", max_corr_distance_m, 0.01, 5.0);
			v.real("z_hit", z_hit, 0.0, 1.0);
			v.real("z_random", z_random, 1e-6, 1.0);
			v.real("occupied_threshold", occupied_threshold, 0.5, 0.9999);
			v.real("max_range_m", max_range_m, 0.1, 200.0);
			v.integer("decimation", decimation, 1, 1000);
		}
	};

	CTiledOccupancyGridMap2D() : CTiledOccupancyGridMap2D(CTiledOccupancyGrid::TOptions()) {}
	explicit CTiledOccupancyGridMap2D(const CTiledOccupancyGrid::TOptions& gridOptions);

	TInsertionOptions insertionOptions;
	TLikelihoodOptions likelihoodOptions;

	const CTiledOccupancyGrid& grid() const { return m_grid; }
	CTiledOccupancyGrid& grid() { return m_grid; }

	/** The merged view over the observed cells (plus `marginCells`), as a
	 * plain MRPT grid (unknown cells at 0.5). */
	mrpt::maps::COccupancyGridMap2D getAsMrptGrid(int marginCells = 0) const;

	/** Options of all kinds as INI text (what serialisation stores). */
	std::string optionsAsIni() const;

	// CMetricMap interface
	bool isEmpty() const override;
	void saveMetricMapRepresentationToFile(const std::string& filNamePrefix) const override;
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& outObj) const override;
	std::string asString() const override;

	MAP_DEFINITION_START(CTiledOccupancyGridMap2D)
	CTiledOccupancyGrid::TOptions gridOpts;
	TInsertionOptions insertionOpts;
	TLikelihoodOptions likelihoodOpts;
	MAP_DEFINITION_END(CTiledOccupancyGridMap2D)

   private:
	void internal_clear() override;
	bool internal_insertObservation(const mrpt::obs::CObservation& obs,
									const std::optional<const mrpt::poses::CPose3D>& robotPose) override;
	double internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
												 const mrpt::poses::CPose3D& takenFrom) const override;
	bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const override;

	/** Distance (m) from a point to the nearest obstacle cell, capped at max_corr_distance_m. */
	double distanceToNearestObstacle(double x_m, double y_m) const;

	CTiledOccupancyGrid m_grid;
};

/** Loads / saves every option of the map (the same keys as the INI
 * definition sections) from / to `cfg`; creationOpts = grid options. */
void loadTiledMapOptions(CTiledOccupancyGrid::TOptions& grid, CTiledOccupancyGridMap2D::TInsertionOptions& ins,
						 CTiledOccupancyGridMap2D::TLikelihoodOptions& lik, const mrpt::config::CConfigFileBase& cfg,
						 const std::string& creationSection, const std::string& insertSection,
						 const std::string& likelihoodSection);

}  // namespace hslam::maps
