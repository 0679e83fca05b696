/* hslam-simulate: simulates the thesis robot (Pioneer P3-DX, SICK LMS,
 * front sonar ring) in a world with walking people and writes an MRPT rawlog
 * with its ground truth (see docs/sim.md).
 *
 *   hslam-simulate -c config_ini/sim-lab.ini -o OUTDIR [--set SECTION.KEY=VALUE ...] [-q]
 */
#include "CSimulationWriter.h"

#include <hslam/common/command_line.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/data_paths.h>
#include <hslam/common/options_io.h>
#include <hslam/common/version.h>
#include <hslam/sim/CSimulator.h>
#include <hslam/sim/scene_rendering.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/img/CImage.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace
{
void writeCorners(const std::string& path, const std::vector<hslam::sim::TWorldCorner>& corners)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error(path + ": cannot open for writing");
	f << "id,x_m,y_m,kind,free_angle_deg,chain\n" << std::fixed << std::setprecision(4);
	for (const auto& c : corners)
		f << c.id << "," << c.point.x << "," << c.point.y << "," << hslam::sim::cornerKindName(c.kind) << ","
		  << std::setprecision(1) << c.free_angle_deg << std::setprecision(4) << "," << c.chain << "\n";
	if (!f) throw std::runtime_error(path + ": write error");
}

void writeGridMap(const std::string& path, const mrpt::maps::COccupancyGridMap2D& grid)
{
	mrpt::io::CFileGZOutputStream out;
	std::string err;
	if (!out.open(path, 1, err)) throw std::runtime_error(path + ": cannot open for writing (" + err + ")");
	auto arch = mrpt::serialization::archiveFrom(out);
	arch << grid;
}

/** config_used.ini and corners.csv: what the run was made of. */
void writeRunInputs(const hslam::sim::TSimulatorConfig& config, const hslam::sim::TScene& scene,
					const std::string& outDir)
{
	mrpt::config::CConfigFileMemory used;
	hslam::sim::saveSimulatorConfig(config, used);
	std::ofstream(outDir + "/config_used.ini") << used.getContent();
	writeCorners(outDir + "/corners.csv", scene.corners);
}

/** The world rasterised at gtResolution_m, written as gt_map.png and gt_map.gridmap.gz. */
mrpt::maps::COccupancyGridMap2D writeGroundTruthMap(const hslam::sim::CWorld& world, double gtResolution_m,
													const std::string& outDir)
{
	const auto gtGrid = hslam::sim::rasterizeWorld(world, gtResolution_m, 1.0);
	if (!gtGrid.saveAsBitmapFile(outDir + "/gt_map.png"))
		throw std::runtime_error(outDir + "/gt_map.png: cannot write");
	writeGridMap(outDir + "/gt_map.gridmap.gz", gtGrid);
	return gtGrid;
}

/** MRPT's (process-wide) serialization setting: RGB images stored as JPEG. */
void configureCameraJpeg(const hslam::sim::TSimulatorConfig& config)
{
	if (!config.camera.enabled || config.camera.jpeg_quality <= 0) return;
	mrpt::img::CImage::DISABLE_JPEG_COMPRESSION(false);
	mrpt::img::CImage::SERIALIZATION_JPEG_QUALITY(config.camera.jpeg_quality);
}

/** Steps the simulator to its end into `writer`; returns the number of steps
 * with the robot body (P3-DX radius 0.25 m) overlapping static geometry. */
long runToEnd(hslam::sim::CSimulator& sim, CSimulationWriter& writer, bool quiet)
{
	int lastReport = -1;
	long collisionSteps = 0;
	while (!sim.done())
	{
		sim.step(writer);
		const auto& p = sim.robot().truePose();
		if (sim.scene().world.collides(mrpt::math::TPoint2D{p.x, p.y}, 0.25)) ++collisionSteps;
		const int tenSeconds = static_cast<int>(sim.elapsed_s() / 10.0);
		if (!quiet && tenSeconds != lastReport)
		{
			lastReport = tenSeconds;
			std::cerr << "\rsimulated " << tenSeconds * 10 << " s" << std::flush;
		}
	}
	if (!quiet) std::cerr << "\n";
	return collisionSteps;
}

void writeOverview(const mrpt::maps::COccupancyGridMap2D& gtGrid, const hslam::sim::CSimulator& sim,
				   const CSimulationWriter& writer, const std::string& outDir)
{
	hslam::sim::TOverviewTracks tracks = writer.tracks();
	tracks.corners = sim.scene().corners;
	if (!hslam::sim::renderOverview(gtGrid, tracks).saveToFile(outDir + "/overview.png"))
		throw std::runtime_error(outDir + "/overview.png: cannot write");
}

/** summary.txt: key=value lines of the finished run. */
std::string summaryText(const hslam::sim::CSimulator& sim, const CSimulationWriter& writer, double physicsDt_s,
						long collisionSteps)
{
	const auto& truth = sim.robot().truePose();
	// The odometry as reported (after [odometry] fault_*) at the last scan.
	const auto& reported = writer.tracks().odometry_path;
	const auto odo = reported.empty() ? sim.robot().odometryPose() : reported.back();
	std::ostringstream summary;
	summary << std::fixed << std::setprecision(3) << "duration_s=" << sim.elapsed_s() << "\n"
			<< "observations=" << writer.rawlog().written() << "\n";
	for (const auto& [label, n] : writer.rawlog().writtenPerLabel()) summary << "observations_" << label << "=" << n << "\n";
	summary << "laser_scans=" << writer.scans() << "\n"
			<< "person_leg_beams=" << writer.personBeams() << "\n"
			<< "sonar_readings=" << writer.sonarReadings() << "\n"
			<< "sonar_echoes=" << writer.sonarEchoes() << "\n"
			<< "sonar_multipath_echoes=" << writer.sonarMultipath() << "\n"
			<< "robot_in_collision_s=" << collisionSteps * physicsDt_s << "\n"
			<< "people=" << sim.scene().people.size() << "\n"
			<< "corners=" << sim.scene().corners.size() << "\n"
			<< "final_true_pose=" << truth.x << " " << truth.y << " " << truth.phi * 180.0 / M_PI << "\n"
			<< "final_odometry_pose=" << odo.x << " " << odo.y << " " << odo.phi * 180.0 / M_PI << "\n"
			<< "final_odometry_error_m=" << std::hypot(truth.x - odo.x, truth.y - odo.y) << "\n";
	return summary.str();
}

int simulate(const std::string& iniFile, const std::vector<std::string>& overrides, const std::string& outDir,
			 double gtResolution_m, bool quiet)
{
	const auto cfg = hslam::common::loadConfigWithOverrides(iniFile, overrides);
	const auto config = hslam::sim::loadSimulatorConfig(cfg);
	const std::string baseDir = std::filesystem::path(iniFile).parent_path().string();
	hslam::sim::TScene scene = hslam::sim::loadScene(config.world, baseDir);
	std::filesystem::create_directories(outDir);
	writeRunInputs(config, scene, outDir);
	const auto gtGrid = writeGroundTruthMap(scene.world, gtResolution_m, outDir);
	configureCameraJpeg(config);

	CSimulationWriter writer(outDir, scene.people.size());
	hslam::sim::CSimulator sim(config, std::move(scene));
	const long collisionSteps = runToEnd(sim, writer, quiet);
	writer.finish();
	writeOverview(gtGrid, sim, writer, outDir);

	const std::string summary = summaryText(sim, writer, config.simulation.physics_dt_s, collisionSteps);
	std::ofstream(outDir + "/summary.txt") << summary;
	if (!quiet) std::cout << summary;
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"hslam-simulate: simulated Pioneer P3-DX with SICK LMS laser, front sonar ring and walking people. "
		"Writes sim.rawlog (MRPT, observations only, gz), ground_truth.tum, odometry.tum, people.csv, "
		"beam_labels.csv, sonar_truth.csv, corners.csv, gt_map.png, gt_map.gridmap.gz, overview.png, "
		"summary.txt and config_used.ini into the output folder.",
		' ', hslam::common::versionText());
	TCLAP::ValueArg<std::string> config("c", "config", "simulator INI (e.g. config_ini/sim-lab.ini; a relative path not found here is looked up in the installed share/hslam) (required)", true, "",
										"file.ini", cmd);
	TCLAP::ValueArg<std::string> output("o", "output", "output folder (created if missing) (required)", true, "", "dir", cmd);
	TCLAP::MultiArg<std::string> set("", "set", "override an INI value, repeatable: --set simulation.seed=7 (repeatable; default: none)", false,
									 "SECTION.KEY=VALUE", cmd);
	TCLAP::ValueArg<double> gtRes("", "gt-resolution", "cell size of the ground-truth map (m) (default: 0.05)", false, 0.05, "m", cmd);
	TCLAP::SwitchArg quiet("q", "quiet", "no progress or summary on the terminal (default: off)", cmd);
	try
	{
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);
		if (!(gtRes.getValue() >= 0.01 && gtRes.getValue() <= 1.0))
			throw std::runtime_error("--gt-resolution must be in [0.01, 1] m");
		return simulate(hslam::common::resolveDataFile(config.getValue()), set.getValue(), output.getValue(), gtRes.getValue(), quiet.getValue());
	}
	catch (const TCLAP::ArgException& e)
	{
		std::cerr << "hslam-simulate: " << e.error() << " (" << e.argId() << ")\n";
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-simulate: error: " << e.what() << "\n";
		return 1;
	}
}
