/* hslam: sonar inverse models for the tiled grid (thesis 4.6.2 iii-iv,
 * 4.6.3, appendix G.3-G.4).
 *
 * A sonar reading (range r, cone half-angle beta) divides its cone into
 *   region 1: the arc of cells at distance r (+- arc_half_width_m) where the
 *             echo came from (likely occupied),
 *   region 2: the cells closer than r - arc_half_width_m (likely empty).
 * Each updated cell at distance d from the sensor and angle alpha from the
 * beam axis gets the confidence (thesis eq. 86-87, with d for the cell's
 * distance as in the thesis' own code, appendix G.3)
 *     s = ((R - d) / R + (beta - |alpha|) / beta) / 2      in [0, 1],
 * R = the sonar's maximum range (5 m on the P3-DX).
 *
 * Two models differ only in WHICH cells they update:
 *   fast      (the thesis' model, 4.6.2 iii, fig. 134): region 1 = the cells
 *             on the arc at radius r only; region 2 = only the cells along
 *             the beam axis (one Bresenham ray). O(r / res) cells.
 *   standard  (Elfes/Moravec shape, the thesis' comparison model, 4.6.3
 *             pseudocode): every cell inside the cone, region 1 or 2.
 *             O((r / res)^2 beta) cells. The thesis looped over every cell of
 *             the 200 x 200 map for each sonar; here only the cone's bounding
 *             box is scanned (same result, far fewer wasted tests), so our
 *             speed-up of fast over standard is smaller than the thesis' 25-30x;
 *             standard_scans_whole_tile = true reproduces the thesis' loop
 *             (every cell of the sensor's tile is tested; same map, for timing).
 *
 * Deviation from eq. 86-87: taken literally, eq. 87 (P = s x Max_occupied)
 * gives P < 0.5 (evidence of FREE space) for the arc cells with s < 0.51, and
 * eq. 86 (P = 1 - s) gives P > 0.5 (OCCUPIED) for region-2 cells with s < 0.5:
 * a far reading near the cone edge would then clear its own echo and mark
 * its empty path occupied. We keep the thesis' shape (strongest near the
 * sensor and on the axis) but map s onto the correct side of 0.5:
 *     region 1: P_occ = 0.5 + (Max_occupied - 0.5) s
 *     region 2: P_occ = 0.5 - (Max_occupied - 0.5) s
 * Both are Bayes updates (eq. 85) in log-odds form; the grid clamps cells at
 * Max_occupied = 0.98.
 *
 * Fusion with the laser (4.6.2 ii, 4.6.4): every sonar log-odds update is
 * multiplied by `weight` (< 1; the laser's updates have weight 1), so where
 * both sensors see a cell the laser dominates, while obstacles seen only by
 * the sonars (glass, which the laser passes through, usually to a range it
 * does not insert) still accumulate and appear.
 *
 * Readings with range 0 (no echo) or beyond max_range_m (thesis: only readings
 * under 3000 mm) are skipped, or with insert_free_beyond_range their region 2
 * is inserted up to max_range_m (no arc). */
#pragma once

#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/poses/CPose2D.h>

#include <string>

namespace hslam::maps
{
/** One sonar reading in world coordinates. */
struct TSonarReading
{
	mrpt::math::TPose2D sensor;  //!< sensor position and beam axis heading (world)
	double range_m = 0;  //!< 0 = no echo
	double cone_aperture_rad = 0;  //!< full cone width
	double sensor_max_range_m = 5.0;  //!< R in eq. 86-87
};

struct TSonarInsertStats
{
	size_t readings_inserted = 0;
	size_t readings_skipped = 0;
	size_t cells_updated = 0;
};

class CSonarGridInserter
{
   public:
	struct TOptions
	{
		std::string model = "fast";  //!< "fast" (thesis 4.6.2 iii) or "standard" (4.6.3)
		double max_range_m = 3.0;  //!< readings beyond are not inserted (thesis: 3000 mm)
		bool insert_free_beyond_range = false;  //!< insert region 2 of longer readings up to max_range_m
		double arc_half_width_m = 0.15;  //!< region 1 = |d - r| <= this (appendix G.3: 150 mm)
		double max_occupied_probability = 0.98;  //!< Max_occupied of eq. 87
		double weight = 0.1;  //!< log-odds weight of sonar updates relative to the laser (1)
		double default_cone_aperture_rad = 23.0 * M_PI / 180.0;  //!< used when an observation has none
																  //!< (appendix G.3: +-11.5 deg)
		bool standard_scans_whole_tile = false;  //!< standard model: test every cell of the sensor's tile

		template <class V>
		void visit(V& v)
		{
			v.choice("model", model, {"fast", "standard"});
			v.real("max_range_m", max_range_m, 0.1, 20.0);
			v.flag("insert_free_beyond_range", insert_free_beyond_range);
			v.real("arc_half_width_m", arc_half_width_m, 0.0, 1.0);
			v.real("max_occupied_probability", max_occupied_probability, 0.51, 0.9999);
			v.real("weight", weight, 0.0, 1.0);
			v.degrees("default_cone_aperture_deg", default_cone_aperture_rad, 1.0, 90.0);
			v.flag("standard_scans_whole_tile", standard_scans_whole_tile);
		}
	};

	CSonarGridInserter() : CSonarGridInserter(TOptions()) {}
	explicit CSonarGridInserter(const TOptions& options);

	/** Inserts one reading. */
	TSonarInsertStats insert(CTiledOccupancyGrid& grid, const TSonarReading& reading) const;

	/** Inserts every reading of a CObservationRange (one entry per sonar,
	 * each with its own pose on the robot) taken at `robotPose`. */
	TSonarInsertStats insert(CTiledOccupancyGrid& grid, const mrpt::poses::CPose2D& robotPose,
							 const mrpt::obs::CObservationRange& obs) const;

	/** Occupancy probability a cell gets from one reading (the per-cell
	 * inverse model shared by both models); region1 = on the arc. */
	double cellProbability(double cellDistance_m, double cellAngleFromAxis_rad, const TSonarReading& r,
						   bool region1) const;

	const TOptions& options() const { return m_options; }

   private:
	float cellLogOdds(double d, double alpha, const TSonarReading& r, bool region1) const;
	size_t insertFast(CTiledOccupancyGrid& grid, const TSonarReading& r, double range, bool withArc) const;
	size_t insertStandard(CTiledOccupancyGrid& grid, const TSonarReading& r, double range, bool withArc) const;

	TOptions m_options;
	bool m_fast;
};

}  // namespace hslam::maps
