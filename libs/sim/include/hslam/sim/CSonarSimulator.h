/* hslam sim: the Pioneer P3-DX front sonar ring (thesis 4.3) with cone,
 * first echo and specular reflection.
 *
 * Ring geometry: the 8 front transducers of the P3-DX, mounting positions and
 * headings from Aria's p3dx-sh.p (relative to the centre of rotation, x forward,
 * y left): 0:(69,136,90) 1:(114,119,50) 2:(148,78,30) 3:(166,27,10)
 * 4:(166,-27,-10) 5:(148,-78,-30) 6:(114,-119,-50) 7:(69,-136,-90) (mm, deg);
 * optionally the rear ring 8-15 (ring = all16): (-157,-136,-90) (-203,-119,-130)
 * (-237,-78,-150) (-255,-27,-170) (-255,27,170) (-237,78,150) (-203,119,130) (-157,136,90).
 *
 * Echo model (the effect thesis 4.3.5-4.3.6 works against): the cone (default
 * 30 deg) is sampled by rays every ray_step_deg. Each ray is traced with
 * specular reflections. At every surface hit, the energy reflected in the
 * mirror direction r returns to the transducer if r points back to it within
 * the specular lobe, i.e. angle(r, hit->sensor) <= 2 * max_incidence (for the
 * first hit this is simply incidence <= max_incidence: a wall seen beyond that
 * angle is a mirror and gives no direct echo). The echo range is half the
 * travelled path (out along the bounces, straight back). With
 * specular_mode = multipath up to max_bounces reflections are followed, which
 * gives both the strong corner echoes (a concave corner is a retro-reflector:
 * two bounces send the ray back) and the long false echoes of rays that leave
 * a grazing wall and return from a far surface; with specular_mode = none only
 * the first hit can echo (grazing walls give no echo at all). The sonar reports
 * the FIRST echo: the shortest range over all rays of its cone. No echo is
 * reported as max_range_m (as the Pioneer reports 5000 mm).
 * Emitted as one CObservationRange with all 8 measurements (sensorID = ring
 * index, sensorPose per measurement, sensorConeApperture, maxSensorDistance). */
#pragma once

#include <hslam/sim/world.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/math/TPose3D.h>
#include <mrpt/obs/CObservationRange.h>

#include <random>
#include <string>
#include <vector>

namespace hslam::sim
{
struct TSonarOptions
{
	bool enabled = true;
	std::string ring = "front8";  //!< front8 (the thesis' front ring) | all16 (front + rear)
	double cone_rad = 30.0 * M_PI / 180.0;  //!< full beam width (thesis/MobileSim ~30 deg)
	double max_range_m = 5.0;  //!< Aria ArSonarDevice 5000 mm
	double min_range_m = 0.1;  //!< echoes nearer than this are reported at this range (ring-down)
	double noise_std_m = 0.01;  //!< Gaussian range noise
	double max_incidence_rad = 25.0 * M_PI / 180.0;  //!< beyond this a surface is a mirror
	std::string specular_mode = "multipath";  //!< none | multipath
	int max_bounces = 2;  //!< reflections followed in multipath mode
	double ray_step_rad = 0.5 * M_PI / 180.0;  //!< angular sampling of the cone
	double rate_hz = 10;  //!< ring readings per second
	double z_m = 0.2;  //!< height of the ring (for sensorPose)
	std::string label = "SONAR";

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.choice("ring", ring, {"front8", "all16"});
		v.degrees("cone_deg", cone_rad, 1.0, 90.0);
		v.real("max_range_m", max_range_m, 0.5, 20.0);
		v.real("min_range_m", min_range_m, 0.0, 1.0);
		v.real("noise_std_m", noise_std_m, 0.0, 1.0);
		v.degrees("max_incidence_deg", max_incidence_rad, 1.0, 89.0);
		v.choice("specular_mode", specular_mode, {"none", "multipath"});
		v.integer("max_bounces", max_bounces, 1, 5);
		v.degrees("ray_step_deg", ray_step_rad, 0.05, 5.0);
		v.real("rate_hz", rate_hz, 0.1, 100.0);
		v.real("z_m", z_m, 0.0, 3.0);
		v.text("label", label);
	}
};

/** Mounting pose of a transducer on the robot (x, y in m, yaw in rad). */
struct TSonarMount
{
	double x_m = 0, y_m = 0, yaw_rad = 0;
};

/** The P3-DX front ring (Aria p3dx-sh.p), indices 0..7 from left (+90 deg) to right (-90 deg). */
std::vector<TSonarMount> p3dxFrontSonarRing();
/** Front ring followed by the rear ring (indices 8..15, right-rear to left-rear). */
std::vector<TSonarMount> p3dxAllSonars();
/** The ring named by TSonarOptions::ring. */
std::vector<TSonarMount> p3dxSonarRing(const std::string& ring);

struct TSonarEcho
{
	bool echo = false;  //!< false: nothing came back within max range
	double range_m = 0;  //!< true (noise-free) echo range, max range if no echo
	int bounces = 0;  //!< 0 = direct echo, >0 = after that many specular reflections
	TObjectTag tag{EObjectKind::none, -1, 0};  //!< object of the last reflection
};

class CSonarSimulator
{
   public:
	CSonarSimulator() : CSonarSimulator(TSonarOptions()) {}
	/** Uses the ring named by options.ring. */
	explicit CSonarSimulator(const TSonarOptions& options);
	CSonarSimulator(const TSonarOptions& options, std::vector<TSonarMount> ring);

	/** Noise-free first echo of one transducer at a world pose. */
	TSonarEcho echo(const CWorld& world, const mrpt::math::TPose2D& sensorWorldPose) const;

	/** One observation with every transducer of the ring (timestamp left to the
	 * caller); `echoes` (optional) receives the noise-free echoes. */
	void simulate(const CWorld& world, const mrpt::math::TPose2D& robotPose, std::mt19937_64& rng,
				  mrpt::obs::CObservationRange& obs, std::vector<TSonarEcho>* echoes = nullptr) const;

	const std::vector<TSonarMount>& ring() const { return m_ring; }
	const TSonarOptions& options() const { return m_opts; }

   private:
	TSonarEcho traceRay(const CWorld& world, const mrpt::math::TPoint2D& sensor, double angle) const;

	TSonarOptions m_opts;
	std::vector<TSonarMount> m_ring;
};

}  // namespace hslam::sim
