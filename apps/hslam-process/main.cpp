/* hslam-process: the batch mapping job. Reads a rawlog (either MRPT format,
 * gz or plain), estimates the robot path, builds the tiled occupancy grid and
 * writes maps, trajectories and timing into an output folder.
 *
 *   hslam-process -c config_ini/hslam-default.ini -i input.rawlog -o outdir
 *                 [--set SECTION.KEY=VALUE ...] [--ground-truth REF.tum] [--quiet]
 */
#include <hslam/common/command_line.h>
#include <hslam/common/data_paths.h>
#include <hslam/common/version.h>
#include <hslam/batch/CBatchProcessor.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

int main(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"hslam-process: batch hybrid SLAM / mapping of a rawlog. Writes map.png, tiles/, "
		"map.gridmap.gz, trajectory.tum, odometry.tum, timing.csv and config_used.ini into the output folder.",
		' ', hslam::common::versionText());
	const std::string defaultConfig = hslam::common::defaultConfigFile();
	TCLAP::ValueArg<std::string> config("c", "config",
										"INI file; a relative path not found here is looked up in the installed "
										"share/hslam (default: " + defaultConfig + ")",
										false, defaultConfig, "file.ini", cmd);
	TCLAP::ValueArg<std::string> input("i", "input", "input rawlog (.rawlog, gz or plain; either MRPT format) (required)",
									   true, "", "file.rawlog", cmd);
	TCLAP::ValueArg<std::string> output("o", "output", "output folder (created if missing) (required)", true, "", "dir", cmd);
	TCLAP::MultiArg<std::string> set("", "set", "override an INI value, repeatable: --set grid.resolution_m=0.05 (repeatable; default: none)",
									 false, "SECTION.KEY=VALUE", cmd);
	TCLAP::ValueArg<std::string> groundTruth("", "ground-truth",
											 "reference trajectory (TUM) to evaluate the estimate against (default: none)", false,
											 "", "ref.tum", cmd);
	TCLAP::SwitchArg quiet("q", "quiet", "no progress bar (default: off)", cmd);
	TCLAP::SwitchArg overwrite("", "overwrite", "write into a non-empty output folder that hslam did not create", cmd);
	try
	{
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);  // help, version or a parse error
		hslam::batch::TBatchRequest request;
		request.config_file = hslam::common::resolveDataFile(config.getValue());
		request.overrides = set.getValue();
		request.input_rawlog = input.getValue();
		request.output_dir = output.getValue();
		request.ground_truth_tum = groundTruth.getValue();
		request.show_progress = !quiet.getValue();
		request.overwrite = overwrite.getValue();
		hslam::batch::CBatchProcessor processor(request, std::cout, std::cerr);
		const auto result = processor.run();
		if (!result.input_error.empty()) return 2;
		if (result.counters.laser_scans == 0)
		{
			// Exit code 3: ran, but the result is empty (issue 15 item 4).
			std::cerr << "hslam-process: warning: no laser scan was used (" << result.counters.entries << " entries read, "
					  << result.counters.laser_scans_ignored
					  << " scans ignored by [process] laser_label): the map and the trajectory are empty\n";
			return 3;
		}
		return 0;
	}
	catch (const TCLAP::ArgException& e)
	{
		std::cerr << "hslam-process: " << e.error() << " (" << e.argId() << ")\n";
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-process: error: " << e.what() << "\n";
		return 1;
	}
}
