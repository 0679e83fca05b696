/* hslam sim: the simulation loop of the thesis robot (P3-DX + SICK LMS +
 * front sonar ring + walking people), as MobileSim was used in the thesis.
 *
 * Fixed physics step (default 10 ms). Every step: the people move (pure
 * functions of time), the controller (waypoint follower, velocity script or
 * an external command) gives (v, w), the robot moves (CDiffDriveRobot), and
 * the sensors whose period is due (integer tick counts, no drift) produce
 * real MRPT observations, handed to an ISimulationSink together with the
 * ground truth of that instant. Deterministic: [simulation] seed seeds one
 * std::mt19937_64 per noise source (robot motion, laser, sonar, camera; via
 * std::seed_seq{seed, source}), each used in a fixed order, so changing a
 * sensor's settings does not change the robot's true path. No file I/O (the app writes). */
#pragma once

#include <hslam/sim/CDiffDriveRobot.h>
#include <hslam/sim/CLaserSimulator.h>
#include <hslam/sim/COdometryFault.h>
#include <hslam/sim/CPathFollower.h>
#include <hslam/sim/CPinholeCameraSimulator.h>
#include <hslam/sim/CSonarSimulator.h>
#include <hslam/sim/ICameraModel.h>
#include <hslam/sim/scene.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <memory>
#include <optional>
#include <random>

namespace hslam::sim
{
struct TSimulationOptions  //!< [simulation]
{
	int seed = 1;
	double physics_dt_s = 0.01;
	double duration_s = 0;  //!< 0 = until the path/script ends (waypoints, velocity modes)
	double max_duration_s = 3600;  //!< safety stop
	double settle_s = 1.0;  //!< keeps simulating this long after the path ended (robot at rest)
	double start_time_s = 1700000000.0;  //!< UNIX time of the first observation (fixed: bit-exact output)

	template <class V>
	void visit(V& v)
	{
		v.integer("seed", seed, 0, 2000000000);
		v.real("physics_dt_s", physics_dt_s, 0.001, 0.1);
		v.real("duration_s", duration_s, 0.0, 1e6);
		v.real("max_duration_s", max_duration_s, 1.0, 1e6);
		v.real("settle_s", settle_s, 0.0, 60.0);
		v.real("start_time_s", start_time_s, 0.0, 4e9);
	}
};

struct TRobotOptions  //!< [robot]
{
	TDiffDriveOptions kinematics;
	double start_x_m = 0, start_y_m = 0, start_yaw_rad = 0;

	template <class V>
	void visit(V& v)
	{
		kinematics.visit(v);
		v.real("start_x_m", start_x_m, -1e5, 1e5);
		v.real("start_y_m", start_y_m, -1e5, 1e5);
		v.degrees("start_yaw_deg", start_yaw_rad, -180.0, 180.0);
	}
};

struct TPathOptions  //!< [path]
{
	std::string mode = "waypoints";  //!< waypoints | velocity | external (setExternalCommand; stops at duration_s or max_duration_s)
	std::string follow = "truth";  //!< pose the follower steers by: truth | odometry (UMBmark)
	std::string waypoints;  //!< "x y; x y; ..." (m)
	int repeat = 1;  //!< the waypoint list is driven this many times
	std::string commands;  //!< velocity mode: "duration_s v_mps w_deg_s; ..."
	TPathFollowerOptions follower;

	template <class V>
	void visit(V& v)
	{
		v.choice("mode", mode, {"waypoints", "velocity", "external"});
		v.choice("follow", follow, {"truth", "odometry"});
		v.text("waypoints", waypoints);
		v.integer("repeat", repeat, 1, 1000);
		v.text("commands", commands);
		follower.visit(v);
	}
};

struct TOdometryOptions  //!< [odometry]
{
	double rate_hz = 10;  //!< Pioneer SIP cycle (100 ms)
	bool quantize = true;  //!< report x, y in whole mm and heading in ARCOS angle units (2 pi / 4096)
	std::string label = "ODOMETRY";
	TOdometryFaultOptions faults;  //!< frozen / missing readings (COdometryFault.h)

	template <class V>
	void visit(V& v)
	{
		v.real("rate_hz", rate_hz, 0.1, 100.0);
		v.flag("quantize", quantize);
		v.text("label", label);
		faults.visit(v);
	}
};

struct TWorldOptions  //!< [world]: where the scene comes from (paths relative to the INI file)
{
	std::string scene_file;  //!< text scene (scene.h format); may be combined with a raster
	std::string map_image;  //!< occupancy image (PNG), dark = occupied
	double map_resolution_m = 0.05;
	double map_origin_x_m = 0, map_origin_y_m = 0;  //!< world position of the image's bottom-left corner
	std::string gridmap_file;  //!< MRPT .gridmap(.gz) as an alternative raster

	template <class V>
	void visit(V& v)
	{
		v.text("scene_file", scene_file);
		v.text("map_image", map_image);
		v.real("map_resolution_m", map_resolution_m, 0.001, 10.0);
		v.real("map_origin_x_m", map_origin_x_m, -1e5, 1e5);
		v.real("map_origin_y_m", map_origin_y_m, -1e5, 1e5);
		v.text("gridmap_file", gridmap_file);
	}
};

struct TSimulatorConfig
{
	TSimulationOptions simulation;
	TWorldOptions world;
	TRobotOptions robot;
	TPathOptions path;
	TOdometryOptions odometry;
	TLaserOptions laser;
	TSonarOptions sonar;
	TCameraSimOptions camera;  //!< [camera] (off by default)
};

/** Loads every section ([simulation], [world], [robot], [path], [odometry],
 * [laser], [sonar], [camera]); unknown sections/keys and bad values throw config_error. */
TSimulatorConfig loadSimulatorConfig(const mrpt::config::CConfigFileBase& cfg);
/** Writes every section (the effective configuration). */
void saveSimulatorConfig(const TSimulatorConfig& config, mrpt::config::CConfigFileBase& cfg);
/** Explicit loader: builds the scene from [world] (files relative to `baseDir`). */
TScene loadScene(const TWorldOptions& world, const std::string& baseDir);

/** Ground truth of the instant an observation was taken. */
struct TSimulationFrame
{
	double t_s = 0;  //!< timestamp (UNIX s) of the observation
	double elapsed_s = 0;  //!< since the start
	mrpt::math::TPose2D true_pose;
	mrpt::math::TPose2D odometry_pose;  //!< as the odometry reports it (after [odometry] fault_*)
	std::vector<TPersonState> people;
};

class ISimulationSink
{
   public:
	virtual ~ISimulationSink() = default;
	virtual void onOdometry(const mrpt::obs::CObservationOdometry& obs, const TSimulationFrame& frame) {}
	virtual void onLaserScan(const mrpt::obs::CObservation2DRangeScan& obs, const std::vector<TObjectTag>& beamTags,
							 const TSimulationFrame& frame)
	{
	}
	virtual void onSonar(const mrpt::obs::CObservationRange& obs, const std::vector<TSonarEcho>& echoes,
						 const TSimulationFrame& frame)
	{
	}
	virtual void onCamera(const mrpt::obs::CObservation& obs, const TSimulationFrame& frame) {}
	/** An odometry reading was due but [odometry] fault = drop withheld it. */
	virtual void onOdometryGap(const TSimulationFrame& frame) {}
	/** The waypoint follower reached waypoint `index` (of the repeated list);
	 * with follow = odometry this is where UMBmark reads the true end pose. */
	virtual void onWaypointReached(size_t index, const TSimulationFrame& frame) {}
};

class CSimulator
{
   public:
	/** Throws std::runtime_error for an unusable path (e.g. waypoints mode without waypoints). */
	CSimulator(const TSimulatorConfig& config, TScene scene);

	/** One physics step: people, controller, robot, due sensors (in this order). */
	void step(ISimulationSink& sink);
	/** Steps until done(). */
	void run(ISimulationSink& sink);
	bool done() const;

	/** Command used in path mode "external" (e.g. from a Pioneer emulator). */
	void setExternalCommand(const TVelocityCommand& command) { m_external = command; }
	void setCamera(std::shared_ptr<const ICameraModel> camera) { m_camera = std::move(camera); }

	double elapsed_s() const { return static_cast<double>(m_tick) * m_cfg.simulation.physics_dt_s; }
	double timestamp_s() const { return m_cfg.simulation.start_time_s + elapsed_s(); }
	const CDiffDriveRobot& robot() const { return m_robot; }
	const TScene& scene() const { return m_scene; }
	const CLaserSimulator& laser() const { return m_laser; }
	const CSonarSimulator& sonar() const { return m_sonar; }
	const TSimulatorConfig& config() const { return m_cfg; }
	/** People states at the current time. */
	std::vector<TPersonState> peopleNow() const;

   private:
	TVelocityCommand controllerCommand(ISimulationSink& sink);
	TSimulationFrame frameNow() const;
	void emitSensors(ISimulationSink& sink);
	long periodTicks(double rate_hz) const;

	TSimulatorConfig m_cfg;
	TScene m_scene;
	std::vector<CWalkingPerson> m_people;
	CDiffDriveRobot m_robot;
	COdometryFault m_odometryFault;
	CLaserSimulator m_laser;
	CSonarSimulator m_sonar;
	std::optional<CPathFollower> m_follower;
	std::optional<CVelocityScript> m_script;
	std::shared_ptr<const ICameraModel> m_camera;
	TVelocityCommand m_external;
	std::mt19937_64 m_rngRobot, m_rngLaser, m_rngSonar, m_rngCamera;
	long m_tick = 0;
	double m_pathEnded_s = -1;  //!< elapsed time the path/script ended (-1 = not yet)
};

}  // namespace hslam::sim
