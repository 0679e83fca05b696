/* hslam sim: CSimulator loop, configuration and scene loading. */
#include <hslam/common/options_io.h>
#include <hslam/sim/CSimulator.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <filesystem>

namespace hslam::sim
{
TSimulatorConfig loadSimulatorConfig(const mrpt::config::CConfigFileBase& cfg)
{
	hslam::common::checkKnownSections(cfg, {"simulation", "world", "robot", "path", "odometry", "laser", "sonar", "camera", "odometry_correction"});
	TSimulatorConfig c;
	hslam::common::loadOptions(c.simulation, cfg, "simulation");
	hslam::common::loadOptions(c.world, cfg, "world");
	hslam::common::loadOptions(c.robot, cfg, "robot");
	hslam::common::loadOptions(c.path, cfg, "path");
	hslam::common::loadOptions(c.odometry, cfg, "odometry");
	hslam::common::loadOptions(c.laser, cfg, "laser");
	hslam::common::loadOptions(c.sonar, cfg, "sonar");
	hslam::common::loadOptions(c.camera, cfg, "camera");
	// Optional UMBmark calibration of the odometry (hslam-umbmark writes it).
	hslam::common::loadOptions(c.robot.kinematics.odometry_correction, cfg, "odometry_correction");
	return c;
}

void saveSimulatorConfig(const TSimulatorConfig& c, mrpt::config::CConfigFileBase& cfg)
{
	hslam::common::saveOptions(c.simulation, cfg, "simulation");
	hslam::common::saveOptions(c.world, cfg, "world");
	hslam::common::saveOptions(c.robot, cfg, "robot");
	hslam::common::saveOptions(c.path, cfg, "path");
	hslam::common::saveOptions(c.odometry, cfg, "odometry");
	hslam::common::saveOptions(c.laser, cfg, "laser");
	hslam::common::saveOptions(c.sonar, cfg, "sonar");
	hslam::common::saveOptions(c.camera, cfg, "camera");
	hslam::common::saveOptions(c.robot.kinematics.odometry_correction, cfg, "odometry_correction");
}

TScene loadScene(const TWorldOptions& w, const std::string& baseDir)
{
	auto resolve = [&](const std::string& p) {
		const std::filesystem::path path(p);
		return (path.is_absolute() || baseDir.empty()) ? path.string() : (std::filesystem::path(baseDir) / path).string();
	};
	TScene scene;
	if (!w.scene_file.empty()) scene = loadSceneFile(resolve(w.scene_file));
	if (!w.map_image.empty() && !w.gridmap_file.empty())
		throw hslam::common::config_error("[world] map_image and gridmap_file: give only one raster");
	if (!w.map_image.empty())
		scene.world.setRaster(
			loadOccupancyImage(resolve(w.map_image), w.map_resolution_m, w.map_origin_x_m, w.map_origin_y_m));
	if (!w.gridmap_file.empty()) scene.world.setRaster(loadGridMapFile(resolve(w.gridmap_file)));
	if (scene.world.bounds().empty())
		throw hslam::common::config_error("[world]: the world is empty (set scene_file, map_image or gridmap_file)");
	return scene;
}

namespace
{
std::mt19937_64 seededStream(int seed, unsigned source)
{
	std::seed_seq seq{static_cast<unsigned>(seed), source};
	return std::mt19937_64(seq);
}
}  // namespace

CSimulator::CSimulator(const TSimulatorConfig& config, TScene scene)
	: m_cfg(config),
	  m_scene(std::move(scene)),
	  m_robot(config.robot.kinematics,
			  mrpt::math::TPose2D{config.robot.start_x_m, config.robot.start_y_m, config.robot.start_yaw_rad}),
	  m_odometryFault(config.odometry.faults,
					  mrpt::math::TPose2D{config.robot.start_x_m, config.robot.start_y_m, config.robot.start_yaw_rad}),
	  m_laser(config.laser),
	  m_sonar(config.sonar),
	  m_rngRobot(seededStream(config.simulation.seed, 1)),
	  m_rngLaser(seededStream(config.simulation.seed, 2)),
	  m_rngSonar(seededStream(config.simulation.seed, 3)),
	  m_rngCamera(seededStream(config.simulation.seed, 4))
{
	for (const auto& p : m_scene.people) m_people.emplace_back(p);
	if (m_cfg.camera.enabled) m_camera = std::make_shared<CPinholeCameraSimulator>(m_cfg.camera);
	const auto& path = m_cfg.path;
	if (path.mode == "waypoints")
	{
		const auto once = parseWaypointList(path.waypoints, "[path] waypoints");
		if (once.empty()) throw hslam::common::config_error("[path] waypoints: empty in mode = waypoints");
		std::vector<mrpt::math::TPoint2D> all;
		for (int r = 0; r < path.repeat; ++r) all.insert(all.end(), once.begin(), once.end());
		m_follower.emplace(path.follower, all);
	}
	else if (path.mode == "velocity")
	{
		auto segs = parseVelocityScript(path.commands, "[path] commands");
		if (segs.empty()) throw hslam::common::config_error("[path] commands: empty in mode = velocity");
		m_script.emplace(segs);
	}
	// mode = external: driven by setExternalCommand(); with duration_s = 0 the
	// caller decides when to stop (done() only at max_duration_s).
}

std::vector<TPersonState> CSimulator::peopleNow() const
{
	std::vector<TPersonState> out;
	for (const auto& p : m_people) out.push_back(p.stateAt(elapsed_s()));
	return out;
}

TVelocityCommand CSimulator::controllerCommand(ISimulationSink& sink)
{
	if (m_follower)
	{
		const auto& pose = m_cfg.path.follow == "odometry" ? m_robot.odometryPose() : m_robot.truePose();
		const size_t before = m_follower->nextWaypoint();
		const auto cmd = m_follower->command(pose);
		if (m_follower->nextWaypoint() != before)
		{
			const TSimulationFrame frame = frameNow();
			for (size_t k = before; k < m_follower->nextWaypoint(); ++k) sink.onWaypointReached(k, frame);
		}
		if (m_follower->finished() && m_pathEnded_s < 0) m_pathEnded_s = elapsed_s();
		return cmd;
	}
	if (m_script)
	{
		if (elapsed_s() >= m_script->duration_s() && m_pathEnded_s < 0) m_pathEnded_s = elapsed_s();
		return m_script->commandAt(elapsed_s());
	}
	return m_external;
}

TSimulationFrame CSimulator::frameNow() const
{
	TSimulationFrame f;
	f.t_s = timestamp_s();
	f.elapsed_s = elapsed_s();
	f.true_pose = m_robot.truePose();
	f.odometry_pose = m_odometryFault.reportedPose();
	f.people = peopleNow();
	return f;
}

long CSimulator::periodTicks(double rate_hz) const
{
	return std::max(1L, std::lround(1.0 / (rate_hz * m_cfg.simulation.physics_dt_s)));
}

namespace
{
mrpt::math::TPose2D pioneerQuantized(const mrpt::math::TPose2D& p)
{
	// ARCOS reports x, y in mm and the heading in 4096 units per turn (AngleConvFactor 0.001534 rad).
	const double angleUnit = 2.0 * M_PI / 4096.0;
	return mrpt::math::TPose2D{std::round(p.x * 1000.0) / 1000.0, std::round(p.y * 1000.0) / 1000.0,
							   mrpt::math::wrapToPi(std::round(p.phi / angleUnit) * angleUnit)};
}
}  // namespace

void CSimulator::emitSensors(ISimulationSink& sink)
{
	const bool odoDue = m_tick % periodTicks(m_cfg.odometry.rate_hz) == 0;
	const bool laserDue = m_cfg.laser.enabled && m_tick % periodTicks(m_cfg.laser.rate_hz) == 0;
	const bool sonarDue = m_cfg.sonar.enabled && m_tick % periodTicks(m_cfg.sonar.rate_hz) == 0;
	const bool cameraDue = m_camera && m_tick % periodTicks(m_camera->rate_hz()) == 0;
	if (!odoDue && !laserDue && !sonarDue && !cameraDue) return;
	const TSimulationFrame frame = frameNow();
	const auto stamp = mrpt::Clock::fromDouble(frame.t_s);
	if (odoDue && m_odometryFault.readingsDropped(frame.elapsed_s))
		sink.onOdometryGap(frame);
	else if (odoDue)
	{
		mrpt::obs::CObservationOdometry odo;
		odo.sensorLabel = m_cfg.odometry.label;
		odo.timestamp = stamp;
		odo.odometry = mrpt::poses::CPose2D(m_cfg.odometry.quantize ? pioneerQuantized(frame.odometry_pose)
																	: frame.odometry_pose);
		odo.hasVelocities = true;
		odo.velocityLocal = m_odometryFault.reportedVelocity(frame.elapsed_s, m_robot.odometryVelocity());
		sink.onOdometry(odo, frame);
	}
	if (laserDue)
	{
		mrpt::obs::CObservation2DRangeScan scan;
		std::vector<TObjectTag> tags;
		m_laser.simulate(m_scene.world, frame.true_pose, m_rngLaser, scan, &tags);
		scan.timestamp = stamp;
		sink.onLaserScan(scan, tags, frame);
	}
	if (sonarDue)
	{
		mrpt::obs::CObservationRange sonar;
		std::vector<TSonarEcho> echoes;
		m_sonar.simulate(m_scene.world, frame.true_pose, m_rngSonar, sonar, &echoes);
		sonar.timestamp = stamp;
		sink.onSonar(sonar, echoes, frame);
	}
	if (cameraDue)
		if (auto obs = m_camera->render(m_scene.world, frame.true_pose, m_rngCamera))
		{
			obs->timestamp = stamp;
			sink.onCamera(*obs, frame);
		}
}

void CSimulator::step(ISimulationSink& sink)
{
	std::vector<TCircle> legs;
	for (const auto& p : m_people)
	{
		auto c = p.legCirclesAt(elapsed_s());
		legs.insert(legs.end(), c.begin(), c.end());
	}
	m_scene.world.setDynamicCircles(std::move(legs));
	emitSensors(sink);
	const TVelocityCommand cmd = controllerCommand(sink);
	m_robot.step(cmd.v_mps, cmd.w_rad_s, m_cfg.simulation.physics_dt_s, m_rngRobot);
	++m_tick;
	m_odometryFault.update(elapsed_s(), m_robot.odometryPose());
}

bool CSimulator::done() const
{
	const double t = elapsed_s();
	if (t >= m_cfg.simulation.max_duration_s) return true;
	if (m_cfg.simulation.duration_s > 0) return t >= m_cfg.simulation.duration_s;
	return m_pathEnded_s >= 0 && t >= m_pathEnded_s + m_cfg.simulation.settle_s;
}

void CSimulator::run(ISimulationSink& sink)
{
	while (!done()) step(sink);
}

}  // namespace hslam::sim
