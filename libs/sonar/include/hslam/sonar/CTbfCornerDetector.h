/* hslam: sonar corner detection by triangulation-based fusion, TBF
 * (thesis 4.3.1-4.3.7, fig. 72 flowchart, appendix B.4; Wijk & Christensen 2000).
 *
 * Sliding window (4.3.1, fig. 72): the last `window_columns` readings (9 in
 * the thesis) of each sonar of the ring, in world coordinates; a new column is
 * added only when the robot moved at least `column_spacing_m` since the last
 * one (a baseline between readings is what makes triangulation possible).
 *
 * For each reading of the newest column, against every reading of the older
 * columns (every sonar, as the thesis' "8 by 9" loop):
 *   1. ranges must agree: |r1 - r2| <= range_agreement_m (300 mm, 4.3.4);
 *   2. triangulate: circle-circle intersection, eq. 43-49 (tbf_geometry.h);
 *   3. keep an intersection only inside both cones (4.3.4), here inside
 *      cone_fraction (0.8) of each half cone: a plane wall echoes at the very
 *      edge of an oblique sonar's cone (where the incidence reaches the
 *      specular limit), and that arc crosses the arcs of perpendicular
 *      readings of the same wall ON the wall at a stable angle: the false
 *      corners "along a line" of thesis 4.3.5 (fig. 75-76), which raising the
 *      stability angle did not remove there. Rejecting the cone's outer rim
 *      removes them (hslam-bench sonar measures it);
 *   4. stability (4.3.5, after [37]): the two arcs must cross at an angle of
 *      at least min_intersection_angle_deg (20 deg); here the angle at the
 *      corner between the directions to the two sensors (grazing crossings
 *      move far along the arcs for a small range error: unstable);
 * the accepted intersections of one reading that agree within
 * hypothesis_radius_m form one corner hypothesis whose hypothesis count n is
 * their number (4.3.4: "a hypothesis counter n is incremented"); hypotheses
 * with n >= min_hypotheses are output.
 *
 * Clustering (the thesis' own suggested fix, 4.3.7: the same corner is
 * re-extracted many times, slightly displaced): a hypothesis within
 * cluster_radius_m of a known corner is merged into it (support-weighted
 * mean); the corner's support is the summed hypothesis count, its covariance
 * the weighted scatter of its members plus a floor of min_std_m^2 (a corner
 * seen once has no scatter yet).
 *
 * Filters can be switched off (use_stability_filter, use_clustering) to
 * measure their effect (hslam-bench sonar). No file I/O. */
#pragma once

#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <vector>

namespace hslam::sonar
{
/** One sonar reading in world coordinates. */
struct TTbfReading
{
	mrpt::math::TPose2D sensor;  //!< transducer position and beam heading (world)
	double range_m = 0;
	double cone_aperture_rad = 0;  //!< full cone width
	int sonar = 0;  //!< index in the ring
	int column = 0;  //!< sliding-window column (increasing)
};

/** One accepted triangulation (for plots and diagnostics). */
struct TTbfIntersection
{
	mrpt::math::TPoint2D point;
	double crossing_angle_rad = 0;  //!< angle of the arcs at the point
	bool stable = false;
};

struct TTbfCorner
{
	mrpt::math::TPoint2D point;
	mrpt::math::CMatrixDouble22 cov;  //!< m^2
	int support = 0;  //!< summed hypothesis counts
	int hypotheses = 0;  //!< hypotheses merged into this corner
};

class CTbfCornerDetector
{
   public:
	static constexpr size_t kMaxKeptIntersections = 20000;

	struct TOptions
	{
		int window_columns = 9;  //!< thesis 4.3.4: 9 columns
		double column_spacing_m = 0.1;  //!< robot travel between columns
		double max_range_m = 3.0;  //!< longer readings are not used (no echo = max range)
		double min_range_m = 0.15;  //!< shorter readings are ring-down, not used
		double range_agreement_m = 0.3;  //!< thesis: 300 mm
		double min_baseline_m = 0.05;  //!< sensors closer than this do not triangulate
		double default_cone_aperture_rad = 30.0 * M_PI / 180.0;  //!< if the observation has none
		double cone_fraction = 0.8;  //!< intersections must lie within this fraction of each half cone (see above)
		bool use_stability_filter = true;
		double min_intersection_angle_rad = 20.0 * M_PI / 180.0;  //!< thesis 4.3.5: 20 deg
		double hypothesis_radius_m = 0.15;  //!< intersections of one reading that agree
		int min_hypotheses = 2;  //!< n needed to output a hypothesis
		bool use_clustering = true;
		double cluster_radius_m = 0.25;  //!< merge hypotheses this close to a corner
		double min_std_m = 0.05;  //!< covariance floor

		template <class V>
		void visit(V& v)
		{
			v.integer("window_columns", window_columns, 2, 100);
			v.real("column_spacing_m", column_spacing_m, 0.0, 2.0);
			v.real("max_range_m", max_range_m, 0.2, 20.0);
			v.real("min_range_m", min_range_m, 0.0, 2.0);
			v.real("range_agreement_m", range_agreement_m, 0.0, 5.0);
			v.real("min_baseline_m", min_baseline_m, 0.001, 2.0);
			v.degrees("default_cone_aperture_deg", default_cone_aperture_rad, 1.0, 90.0);
			v.real("cone_fraction", cone_fraction, 0.1, 1.0);
			v.flag("use_stability_filter", use_stability_filter);
			v.degrees("min_intersection_angle_deg", min_intersection_angle_rad, 0.0, 90.0);
			v.real("hypothesis_radius_m", hypothesis_radius_m, 0.01, 2.0);
			v.integer("min_hypotheses", min_hypotheses, 1, 100);
			v.flag("use_clustering", use_clustering);
			v.real("cluster_radius_m", cluster_radius_m, 0.01, 5.0);
			v.real("min_std_m", min_std_m, 0.0, 1.0);
		}
	};

	CTbfCornerDetector() : CTbfCornerDetector(TOptions()) {}
	explicit CTbfCornerDetector(const TOptions& options);

	/** Processes one ring observation taken at `robotPose`. Returns true if
	 * it became a new window column (the robot moved far enough). */
	bool process(const mrpt::poses::CPose2D& robotPose, const mrpt::obs::CObservationRange& obs);

	/** Adds one column of readings (world coordinates) and triangulates it
	 * against the window. */
	void addColumn(std::vector<TTbfReading> readings);

	/** Corners so far (clustered if use_clustering, else every hypothesis). */
	const std::vector<TTbfCorner>& corners() const { return m_corners; }
	/** Corners with at least `minSupport`. */
	std::vector<TTbfCorner> corners(int minSupport) const;
	/** The most recent in-cone intersections (stable or not; at most
	 * kMaxKeptIntersections, for plots and diagnostics). */
	const std::vector<TTbfIntersection>& intersections() const { return m_intersections; }
	const TOptions& options() const { return m_options; }
	void clear();

   private:
	/** Accepted intersection of reading `a` (newest column) with `b`, if any. */
	bool triangulate(const TTbfReading& a, const TTbfReading& b, TTbfIntersection& out) const;
	void addHypothesis(const mrpt::math::TPoint2D& p, int count);

	TOptions m_options;
	std::deque<std::vector<TTbfReading>> m_window;  //!< oldest first
	int m_nextColumn = 0;
	bool m_havePose = false;
	mrpt::math::TPose2D m_lastColumnPose;
	std::vector<TTbfIntersection> m_intersections;
	std::vector<TTbfCorner> m_corners;
	std::vector<std::vector<std::pair<mrpt::math::TPoint2D, int>>> m_members;  //!< per corner
};

}  // namespace hslam::sonar
