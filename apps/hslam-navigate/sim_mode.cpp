/* hslam-navigate: simulated robot (see sim_mode.h). */
#include "sim_mode.h"

#include <hslam/common/tum_trajectory.h>
#include <hslam/sim/CSubsumptionDriver.h>
#include <hslam/sim/scene_rendering.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>
#include <iostream>

namespace hslam::apps
{
namespace
{
/** Records every observation, maps the scans at the true pose, keeps the truth. */
class CRecordingSink : public sim::ISimulationSink
{
   public:
	explicit CRecordingSink(CNavigationLog& log) : m_log(log) {}
	void onOdometry(const mrpt::obs::CObservationOdometry& o, const sim::TSimulationFrame& f) override
	{
		m_log.observation(o);
		truth.push_back({f.t_s, f.true_pose});
	}
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan& o, const std::vector<sim::TObjectTag>&,
					 const sim::TSimulationFrame& f) override
	{
		m_log.observation(o);
		m_log.mapScan(o, f.true_pose);
	}
	void onSonar(const mrpt::obs::CObservationRange& o, const std::vector<sim::TSonarEcho>&,
				 const sim::TSimulationFrame&) override
	{
		m_log.observation(o);
	}
	common::TTrajectory2D truth;

   private:
	CNavigationLog& m_log;
};

/** Our controller, also logging every command into the path CSV. */
class CLoggingDriver : public sim::CSubsumptionDriver
{
   public:
	CLoggingDriver(const nav::TSubsumptionOptions& o, std::vector<mrpt::math::TPoint2D> t, CNavigationLog& log)
		: CSubsumptionDriver(o, std::move(t)), m_log(log)
	{
	}
	sim::TControlOutput control(const sim::TControlInput& in) override
	{
		const auto out = CSubsumptionDriver::control(in);
		m_log.sample({in.t_s, in.pose, last.v_mps, last.w_rad_s, nav::navStateName(last.state), last.nearest_m,
					  last.targets_reached, nav::navLayerName(last.layer)});
		return out;
	}

   private:
	CNavigationLog& m_log;
};
}  // namespace

TSimDriveResult driveSimulated(const std::string& simIni, const nav::TSubsumptionOptions& options,
							   const std::vector<mrpt::math::TPoint2D>& targets, double timeout_s, CNavigationLog& log,
							   const std::string& outDir)
{
	if (!mrpt::system::fileExists(simIni)) throw std::runtime_error(simIni + ": not found");
	mrpt::config::CConfigFile ini(simIni);
	auto config = sim::loadSimulatorConfig(ini);
	config.path.mode = "external";
	config.simulation.duration_s = 0;
	config.simulation.max_duration_s = std::max(config.simulation.max_duration_s, timeout_s + 10);
	const auto scene = sim::loadScene(config.world, std::filesystem::path(simIni).parent_path().string());
	sim::CSimulator simulator(config, scene);
	CRecordingSink sink(log);
	CLoggingDriver driver(options, targets, log);
	sim::TClosedLoopOptions loop;
	loop.timeout_s = timeout_s;
	loop.use_odometry_pose = false;
	TSimDriveResult res;
	res.loop = sim::runClosedLoop(simulator, driver, loop, &sink);
	res.targets_reached = driver.last.targets_reached;
	common::writeTumFile((std::filesystem::path(outDir) / "ground_truth.tum").string(), sink.truth);
	const auto gt = sim::rasterizeWorld(scene.world, 0.05, 0.5);
	gt.saveAsBitmapFile((std::filesystem::path(outDir) / "gt_map.png").string());
	log.renderPath(gt, targets).saveToFile((std::filesystem::path(outDir) / "path.png").string());
	return res;
}

}  // namespace hslam::apps
