/* hslam nav: laser and sonar fused into one polar range profile around the
 * robot centre (thesis 4.2.3: "it is easier to integrate the laser and sonar
 * sensors together"; 4.9.2: the laser sees chair legs, the sonar cone sees
 * what lies between the beams).
 *
 * The profile has one bin per bin_deg over 360 deg, robot frame, angle 0 =
 * ahead, CCW positive; each bin holds the nearest range (m, from the robot
 * centre) any sensor reported in it. A laser beam fills the bin of its end
 * point; a sonar echo fills every bin its cone (cone_deg) covers at its range,
 * as the echo may come from anywhere in the cone. Bins nothing saw hold
 * max_range. The layers read the profile through virtual sonars (the eight
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

	template <class V>
	void visit(V& v)
	{
		v.degrees("bin_deg", bin_rad, 0.25, 10.0);
		v.real("max_range_m", max_range_m, 0.5, 30.0);
		v.degrees("sonar_cone_deg", sonar_cone_rad, 1.0, 90.0);
		v.flag("use_laser", use_laser);
		v.flag("use_sonar", use_sonar);
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

	size_t size() const { return m_ranges.size(); }
	double binAngle(size_t i) const;
	double range(size_t i) const { return m_ranges[i]; }
	double maxRange() const { return m_maxRange; }

   private:
	size_t binOf(double angle_rad) const;
	double m_bin;
	double m_maxRange;
	std::vector<double> m_ranges;
};

class CRangeFusion
{
   public:
	explicit CRangeFusion(const TRangeFusionOptions& options = {}) : m_opts(options) {}

	/** Fused profile of the latest scan and sonar ring (either may be null). */
	CPolarProfile fuse(const mrpt::obs::CObservation2DRangeScan* scan, const mrpt::obs::CObservationRange* sonar) const;

	const TRangeFusionOptions& options() const { return m_opts; }

   private:
	TRangeFusionOptions m_opts;
};

}  // namespace hslam::nav
