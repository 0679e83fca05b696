/* hslam-umbmark --drive (see umbmark_drive.h). */
#include "umbmark_drive.h"

#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogObservationWriter.h>
#include <hslam/sim/CSimulator.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace hslam::apps
{
namespace
{
/** Records the odometry, laser and sonar into the rawlog and the true pose of
 * every odometry reading (its timestamp) into the trajectory. */
class CUmbmarkRecorder : public sim::ISimulationSink
{
   public:
	explicit CUmbmarkRecorder(const std::string& rawlog) : m_rawlog(rawlog) {}
	void onOdometry(const mrpt::obs::CObservationOdometry& o, const sim::TSimulationFrame& f) override
	{
		m_rawlog.write(o);
		truth.push_back({f.t_s, f.true_pose});
	}
	void onLaserScan(const mrpt::obs::CObservation2DRangeScan& o, const std::vector<sim::TObjectTag>&,
					 const sim::TSimulationFrame&) override
	{
		m_rawlog.write(o);
	}
	void onSonar(const mrpt::obs::CObservationRange& o, const std::vector<sim::TSonarEcho>&,
				 const sim::TSimulationFrame&) override
	{
		m_rawlog.write(o);
	}
	void close() { m_rawlog.close(); }
	common::TTrajectory2D truth;

   private:
	io::CRawlogObservationWriter m_rawlog;
};

std::string resolveBeside(const std::string& base, const std::string& relative)
{
	const std::filesystem::path p(relative);
	return p.is_absolute() ? relative : (std::filesystem::path(base).parent_path() / p).string();
}
}  // namespace

TUmbmarkDriveOptions loadDriveOptions(const std::string& path)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": not found");
	try
	{
		mrpt::config::CConfigFile cfg(path);
		common::checkKnownSections(cfg, {"umbmark_drive"});
		TUmbmarkDriveOptions o;
		common::loadOptions(o, cfg, "umbmark_drive");
		return o;
	}
	catch (const common::config_error& e)
	{
		throw std::runtime_error(path + ": " + e.what());
	}
}

std::string umbmarkSquareWaypoints(const TUmbmarkDriveOptions& o)
{
	std::ostringstream w;
	const double x0 = o.start_x_m, y0 = o.start_y_m, L = o.side_m;
	for (const double sign : {-1.0, 1.0})  // clockwise (right turns) first, then counter-clockwise
		for (int run = 0; run < o.runs_per_direction; ++run)
			w << x0 + L << " " << y0 << "; " << x0 + L << " " << y0 + sign * L << "; " << x0 << " "
			  << y0 + sign * L << "; " << x0 << " " << y0 << "; ";
	std::string s = w.str();
	return s.substr(0, s.size() - 2);
}

TUmbmarkDriveOutput driveUmbmark(const std::string& driveIni, const TUmbmarkDriveOptions& o, const std::string& outDir)
{
	const std::string simIni = resolveBeside(driveIni, o.sim_ini);
	if (!mrpt::system::fileExists(simIni))
		throw std::runtime_error(driveIni + ": [umbmark_drive] sim_ini: " + simIni + " not found");
	TUmbmarkDriveOutput out;
	out.rawlog = (std::filesystem::path(outDir) / "umbmark.rawlog").string();
	out.truth = (std::filesystem::path(outDir) / "ground_truth.tum").string();
	if (std::filesystem::exists(out.rawlog))
		throw std::runtime_error(outDir + ": holds a previous run (umbmark.rawlog); choose another --drive-out");
	std::filesystem::create_directories(outDir);
	auto config = sim::loadSimulatorConfig(mrpt::config::CConfigFile(simIni));
	config.path.mode = "waypoints";
	config.path.follow = "odometry";  // the square is driven by odometry (thesis 4.1)
	config.path.waypoints = umbmarkSquareWaypoints(o);
	config.path.repeat = 1;
	config.robot.start_x_m = o.start_x_m;
	config.robot.start_y_m = o.start_y_m;
	config.robot.start_yaw_rad = 0;
	config.simulation.duration_s = 0;  // until the last corner
	const auto scene = sim::loadScene(config.world, std::filesystem::path(simIni).parent_path().string());
	sim::CSimulator simulator(config, scene);
	CUmbmarkRecorder recorder(out.rawlog);
	simulator.run(recorder);
	recorder.close();
	if (recorder.truth.empty()) throw std::runtime_error(simIni + ": the simulation produced no odometry");
	out.sim_time_s = recorder.truth.back().t_s - recorder.truth.front().t_s;
	common::writeTumFile(out.truth, recorder.truth);
	return out;
}

}  // namespace hslam::apps
