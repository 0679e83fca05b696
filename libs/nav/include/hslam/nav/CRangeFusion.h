/* hslam nav: laser and sonar fused into one polar range profile around the
 * robot centre (thesis 4.2.3: "it is easier to integrate the laser and sonar
 * sensors together"; 4.9.2: the laser sees chair legs, the sonar cone sees
 * what lies between the beams).
 *
 * The profile has one bin per bin_deg over 360 deg, robot frame, angle 0 =
 * ahead, CCW positive; each bin holds the nearest range (m, from the robot
 * centre) any sensor reported in it. A laser beam fills the bin of its end
 * point; a sonar echo fills every bin its cone (cone_deg) covers at its range,
 * as the echo may come from anywhere in the cone, unless the laser already
 * explains it (below). Bins nothing saw hold max_range.
 *
 * Explained echoes (not in the thesis; docs/nav.md "Deviations"): a sonar
 * echo at range r says that the first reflector in its cone lies at r. When
 * the laser sees, inside that cone, a surface no farther than r +
 * explained_tolerance_mm (from the sonar), the echo adds nothing the profile
 * lacks: it came from that surface, or from beyond a surface the sonar missed
 * (specular, multipath), and the laser has placed that surface bin by bin.
 * Only an echo nearer than everything the laser saw in the cone is something
 * the laser cannot see (thesis 4.9.1: chair legs between the beams, glass, low
 * objects) and fills its cone. Filling every cone hid the 0.9 m doorway: near
 * a jamb the echo of the jamb, or a multipath echo at 1.2 m, covered the whole
 * 30 deg cone over the opening the laser saw 4-5 m deep. The layers read the profile through virtual sonars (the eight
 * P3-DX ring directions) and sector queries, so eq. 34 and the side layer work
 * the same whether the ranges came from sonars, the laser or both. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationRange.h>

#include <vector>

namespace hslam::nav
{
struct TRangeFusionOptions
{
	double bin_rad = 2.0 * M_PI / 180.0;  //!< angular size of a profile bin
	double max_range_m = 5.0;  //!< thesis: sonar maximum range 5000 mm
	double sonar_cone_rad = 30.0 * M_PI / 180.0;  //!< full cone of a P3-DX sonar (Polaroid 6500)
	bool use_laser = true;
	bool use_sonar = true;
	bool drop_explained_sonar = true;  //!< an echo the laser explains does not fill its cone (header)
	double explained_tolerance_mm = 100;  //!< laser surface at most r + this (from the sonar) explains an echo at r

	template <class V>
	void visit(V& v)
	{
		v.degrees("bin_deg", bin_rad, 0.25, 10.0);
		v.real("max_range_m", max_range_m, 0.5, 30.0);
		v.degrees("sonar_cone_deg", sonar_cone_rad, 1.0, 90.0);
		v.flag("use_laser", use_laser);
		v.flag("use_sonar", use_sonar);
		v.flag("drop_explained_sonar", drop_explained_sonar);
		v.real("explained_tolerance_mm", explained_tolerance_mm, 0.0, 2000.0);
	}
};

class CPolarProfile
{
   public:
	CPolarProfile(double bin_rad, double maxRange_m);

	void clear();
	/** Lowers the bin of `angle_rad` to range_m (if nearer). */
	void addPoint(double angle_rad, double range_m);
	/** Minimum range over [from_rad, to_rad] (robot frame, from <= to). */
	double minRange(double from_rad, double to_rad) const;
	/** Free distance along a straight corridor of half-width halfWidth_m in direction heading_rad. */
	double corridorFreeDistance(double heading_rad, double halfWidth_m) const;
	/** corridorFreeDistance for the headings k step_rad, k = -n..n, into free[k + n] (resized).
	 * One pass over the bins: a point at range r blocks only the headings
	 * within asin(halfWidth / r) of its bearing, so each point visits a few
	 * headings instead of every one (the same values as one call per heading). */
	void corridorFreeDistances(double step_rad, int n, double halfWidth_m, std::vector<double>& free) const;

	size_t size() const { return m_ranges.size(); }
	double binAngle(size_t i) const;
	double range(size_t i) const { return m_ranges[i]; }
	double maxRange() const { return m_maxRange; }
	double binSize() const { return m_bin; }
	/** Robot-frame point of bin i (its range at the bin's centre angle). */
	double pointX(size_t i) const { return m_ranges[i] * m_cos[i]; }
	double pointY(size_t i) const { return m_ranges[i] * m_sin[i]; }

   private:
	size_t binOf(double angle_rad) const;
	double m_bin;
	double m_maxRange;
	std::vector<double> m_ranges;
	std::vector<double> m_cos, m_sin;  //!< of each bin's centre angle
	mutable std::vector<double> m_gridCos, m_gridSin;  //!< corridorFreeDistances' headings
	mutable double m_gridStep = 0;
	mutable int m_gridN = -1;
};

class CRangeFusion
{
   public:
	explicit CRangeFusion(const TRangeFusionOptions& options = {}) : m_opts(options) {}

	/** Fused profile of the latest scan and sonar ring (either may be null). */
	CPolarProfile fuse(const mrpt::obs::CObservation2DRangeScan* scan, const mrpt::obs::CObservationRange* sonar);
	/** The same into `out` (cleared first; made with this fusion's bin and
	 * range, see makeProfile()): no allocation once the buffers have grown. */
	void fuseInto(CPolarProfile& out, const mrpt::obs::CObservation2DRangeScan* scan,
				  const mrpt::obs::CObservationRange* sonar);
	CPolarProfile makeProfile() const { return CPolarProfile(m_opts.bin_rad, m_opts.max_range_m); }

	const TRangeFusionOptions& options() const { return m_opts; }

   private:
	/** Whether a laser point lies in the echo's cone no farther than its range + tolerance. */
	bool laserExplains(const mrpt::obs::CObservationRange::TMeasurement& echo) const;
	TRangeFusionOptions m_opts;
	std::vector<double> m_laserX, m_laserY;  //!< this step's laser end points (robot frame), reused
	std::vector<double> m_beamCos, m_beamSin;  //!< per beam direction (sensor frame), cached for the scan geometry
	size_t m_beamCount = 0;
	double m_beamAperture = 0;
	bool m_beamRightToLeft = true;
};

}  // namespace hslam::nav
