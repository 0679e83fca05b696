/* hslam sim: SICK LMS laser scanner model (thesis 3.x hardware: SICK LMS200 on
 * the P3-DX). One exact ray per beam against the world (walls, furniture,
 * people's legs), Gaussian range noise, range quantisation, max range.
 * Optional artefacts of real scanners (all off by default): lost returns
 * (glass, black surfaces), spurious short returns (dust, reflections) and
 * mixed pixels at range discontinuities (the SICK LMS's beam spot straddles
 * an edge and reports a range between the two surfaces).
 * Output is a real mrpt::obs::CObservation2DRangeScan in MRPT's convention
 * (rightToLeft, beam i at -fov/2 + i*fov/(N-1) in the sensor frame, beams
 * beyond max range invalid with range = maxRange), plus the object tag of
 * every beam (which person/leg it hit) for per-beam ground truth.
 *
 * Presets: lms200 = 181 beams over 180 deg (1 deg), 8 m (the SICK's 8 m/cm mode);
 *          lms100 = 541 beams over 270 deg (0.5 deg), 20 m;
 *          custom = fov_deg / resolution_deg / max_range_m as given. */
#pragma once

#include <hslam/sim/world.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <random>
#include <string>
#include <vector>

namespace hslam::sim
{
struct TLaserOptions
{
	bool enabled = true;
	std::string preset = "lms200";  //!< lms200 | lms100 | custom
	double fov_rad = M_PI;  //!< used with preset = custom
	double resolution_rad = M_PI / 180.0;  //!< used with preset = custom
	double max_range_m = 0;  //!< 0 = the preset's (lms200 8 m, lms100 20 m, custom 8 m)
	double noise_std_m = 0.01;  //!< Gaussian range noise (LMS200 datasheet: ~1 cm)
	double range_resolution_m = 0.01;  //!< reported range step (cm mode); 0 = none
	double rate_hz = 10;  //!< scans per second (thesis: 10 Hz processing)
	double dropout_probability = 0;  //!< a return is lost (reported invalid)
	double spurious_probability = 0;  //!< a return is replaced by a short one, uniform in [0.1 m, true range)
	/** At a discontinuity of more than mixed_pixel_jump_m between neighbouring
	 * beams, the nearer surface's edge beam returns a range uniform between
	 * the two surfaces with this probability. */
	double mixed_pixel_probability = 0;
	double mixed_pixel_jump_m = 0.3;
	double x_m = 0.021, y_m = 0, z_m = 0.3, yaw_rad = 0;  //!< sensor pose on the robot (Aria LaserX 21 mm)
	/** Mounted upside down (roll 180 deg in the scan's sensorPose): the beams
	 * sweep clockwise seen from above, as such a laser's do. */
	bool upside_down = false;
	std::string label = "LASER";

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.choice("preset", preset, {"lms200", "lms100", "custom"});
		v.degrees("fov_deg", fov_rad, 1.0, 360.0);
		v.degrees("resolution_deg", resolution_rad, 0.05, 10.0);
		v.real("max_range_m", max_range_m, 0.0, 100.0);
		v.real("noise_std_m", noise_std_m, 0.0, 1.0);
		v.real("range_resolution_m", range_resolution_m, 0.0, 0.1);
		v.real("rate_hz", rate_hz, 0.1, 100.0);
		v.real("dropout_probability", dropout_probability, 0.0, 1.0);
		v.real("spurious_probability", spurious_probability, 0.0, 1.0);
		v.real("mixed_pixel_probability", mixed_pixel_probability, 0.0, 1.0);
		v.real("mixed_pixel_jump_m", mixed_pixel_jump_m, 0.01, 100.0);
		v.real("x_m", x_m, -2.0, 2.0);
		v.real("y_m", y_m, -2.0, 2.0);
		v.real("z_m", z_m, 0.0, 3.0);
		v.degrees("yaw_deg", yaw_rad, -180.0, 180.0);
		v.flag("upside_down", upside_down);
		v.text("label", label);
	}
};

class CLaserSimulator
{
   public:
	CLaserSimulator() : CLaserSimulator(TLaserOptions()) {}
	explicit CLaserSimulator(const TLaserOptions& options);

	size_t beamCount() const { return m_beams; }
	double fov_rad() const { return m_fov; }
	double maxRange_m() const { return m_maxRange; }
	/** Beam angle in the sensor frame (rad). */
	double beamAngle(size_t i) const;

	/** Fills `scan` (timestamp left to the caller) and, if given, the tag of
	 * the object each beam hit (kind none for no hit). */
	void simulate(const CWorld& world, const mrpt::math::TPose2D& robotPose, std::mt19937_64& rng,
				  mrpt::obs::CObservation2DRangeScan& scan, std::vector<TObjectTag>* beamTags = nullptr) const;

	const TLaserOptions& options() const { return m_opts; }

   private:
	/** The artefacts (dropout, spurious, mixed pixels) on one scan's true
	 * ranges; draws nothing when all are off (samples stay as they were). */
	void addArtefacts(std::vector<double>& range_m, std::vector<char>& valid, std::mt19937_64& rng) const;

	TLaserOptions m_opts;
	size_t m_beams = 181;
	double m_fov = M_PI, m_maxRange = 8.0;
};

}  // namespace hslam::sim
