/* hslam-umbmark: UMBmark odometry calibration (thesis 4.1, eq. 21-31).
 *
 *   hslam-umbmark FOLDER                  simulator output (waypoints.csv + ground_truth.tum)
 *   hslam-umbmark -i RAWLOG [--truth TUM] a recording + the true poses
 *   hslam-umbmark --endpoints CSV --side-m L   end points typed in (thesis tables 1-2)
 *   hslam-umbmark --drive DRIVE.ini [--drive-out DIR]   drives the square itself (simulated
 *                                         P3-DX), records DIR/umbmark.rawlog + ground_truth.tum,
 *                                         then evaluates that recording like -i
 *
 * Prints the per-run errors, centres of gravity, alpha, beta, R, the corrected
 * wheelbase, the encoder factors and E_max,syst, ending with "Ed=" and "Eb="
 * lines; -o writes the [odometry_correction] INI section. Exit 0 on success,
 * 1 on any error. */
#include "umbmark_drive.h"
#include "umbmark_inputs.h"
#include "umbmark_report.h"

#include <hslam/common/version.h>
#include <hslam/common/command_line.h>
#include <hslam/common/parse_number.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace
{
using namespace hslam;

double positiveNumber(const std::string& text, const std::string& option)
{
	const auto v = common::tryParseDouble(text);
	if (!v || *v <= 0) throw std::runtime_error(option + ": expected a positive number, got '" + text + "'");
	return *v;
}

/** Runs of a folder or a rawlog; `source` and the side length are filled in. */
std::vector<calib::TUmbmarkEndpoint> runsFromPoses(const std::vector<calib::TPosePair>& poses,
												   calib::TUmbmarkOptions& options, bool sideGiven)
{
	const auto split = calib::splitUmbmarkRuns(poses);
	if (split.endpoints.empty()) throw std::runtime_error("no closed square found in the odometry");
	if (!sideGiven) options.side_length_m = split.mean_side_length_m;
	return split.endpoints;
}

/** --drive: drives the square (thesis 4.1), then reads the recording like -i. */
std::vector<calib::TPosePair> driveAndRead(const std::string& driveIni, const std::string& outDir, std::string& source)
{
	const auto options = apps::loadDriveOptions(driveIni);
	const auto rec = apps::driveUmbmark(driveIni, options, outDir);
	std::cout << "drove " << options.runs_per_direction << " CW + " << options.runs_per_direction << " CCW squares of "
			  << options.side_m << " m in " << rec.sim_time_s << " s (simulated); recording: " << rec.rawlog << "\n";
	source = rec.rawlog;
	return apps::readRawlogWithTruth(rec.rawlog, rec.truth);
}

int evaluateEndpointTable(const std::string& path, calib::TUmbmarkOptions options, const std::string& iniOut)
{
	const auto table = apps::readEndpointCsv(path);
	std::vector<calib::TUmbmarkEndpoint> all;
	for (const auto& g : table.groups)
	{
		const auto& runs = table.runs.at(g);
		all.insert(all.end(), runs.begin(), runs.end());
		std::cout << "=== group " << g << " ===\n";
		try
		{
			apps::printUmbmark(std::cout, runs, calib::computeUmbmark(runs, options), options);
		}
		catch (const std::invalid_argument& e)
		{
			std::cout << "  skipped: " << e.what() << "\n";
		}
	}
	std::cout << "=== all groups pooled ===\n";
	const auto result = calib::computeUmbmark(all, options);
	apps::printUmbmark(std::cout, all, result, options);
	if (!iniOut.empty()) apps::writeCorrectionIni(iniOut, result, options, path);
	return 0;
}
/** The computation's options from the command line (side "" = from the odometry). */
calib::TUmbmarkOptions umbmarkOptions(bool exactModel, const std::string& wheelbase, const std::string& side)
{
	calib::TUmbmarkOptions options;
	options.exact_model = exactModel;
	options.nominal_wheelbase_m = positiveNumber(wheelbase, "--wheelbase-m");
	if (!side.empty()) options.side_length_m = positiveNumber(side, "--side-m");
	return options;
}

/** -i RAWLOG with --truth TUM (default: ground_truth.tum beside the rawlog). */
std::vector<calib::TPosePair> readRawlogInput(const std::string& rawlog, const std::string& truth)
{
	return apps::readRawlogWithTruth(
		rawlog, !truth.empty() ? truth : (std::filesystem::path(rawlog).parent_path() / "ground_truth.tum").string());
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TCLAP::CmdLine cmd("UMBmark odometry calibration (thesis 4.1): CW/CCW centres of gravity, alpha, beta, R, "
						   "Ed, Eb, encoder factors, E_max,syst; writes the [odometry_correction] INI section.",
						   ' ', hslam::common::versionText());
		TCLAP::UnlabeledValueArg<std::string> folderArg(
			"folder", "Simulator UMBmark folder with waypoints.csv and ground_truth.tum (e.g. rawlog_samples/umbmark)",
			false, "", "FOLDER", cmd);
		TCLAP::ValueArg<std::string> rawlogArg("i", "input", "Rawlog of a UMBmark run (odometry)", false, "", "RAWLOG",
											   cmd);
		TCLAP::ValueArg<std::string> truthArg("", "truth", "True poses for -i (default: ground_truth.tum beside it)",
											  false, "", "TUM", cmd);
		TCLAP::ValueArg<std::string> endpointsArg("", "endpoints", "End-point errors as CSV group,direction,x_cm,y_cm",
												  false, "", "CSV", cmd);
		TCLAP::ValueArg<std::string> driveArg(
			"", "drive",
			"Drive the UMBmark square (thesis 4.1) with the simulated P3-DX of this INI's [umbmark_drive] "
			"(config_ini/umbmark-drive.ini), record it, evaluate the recording",
			false, "", "DRIVE.ini", cmd);
		TCLAP::ValueArg<std::string> driveOutArg("", "drive-out", "Folder for --drive's recording (created)", false,
												 "hslam-umbmark-drive", "DIR", cmd);
		TCLAP::ValueArg<std::string> sideArg("", "side-m", "Side of the square L (m); default: from the odometry",
											 false, "", "L", cmd);
		TCLAP::ValueArg<std::string> wheelbaseArg("", "wheelbase-m", "Nominal wheelbase b (m)", false, "0.335", "B",
												  cmd);
		TCLAP::SwitchArg firstOrderArg("", "first-order",
									   "Use eq. 23-24 as printed (no exact-square refinement of alpha, beta)", cmd);
		TCLAP::ValueArg<std::string> iniArg("o", "output-ini", "Write the [odometry_correction] section here (new file)",
											false, "", "OUT.ini", cmd);
		if (!cmd.parse(argc, argv)) return common::exitCodeAfterParseStop(argc, argv);

		auto options = umbmarkOptions(!firstOrderArg.getValue(), wheelbaseArg.getValue(),
											sideArg.isSet() ? sideArg.getValue() : "");
		const int inputs = folderArg.isSet() + rawlogArg.isSet() + endpointsArg.isSet() + driveArg.isSet();
		if (inputs != 1)
			throw std::runtime_error("give exactly one input: FOLDER, -i RAWLOG, --endpoints CSV or --drive INI");
		if (endpointsArg.isSet())
		{
			if (!sideArg.isSet()) throw std::runtime_error("--endpoints needs --side-m (thesis: 4.4)");
			return evaluateEndpointTable(endpointsArg.getValue(), options, iniArg.getValue());
		}
		std::string source = folderArg.isSet() ? folderArg.getValue() : rawlogArg.getValue();
		std::vector<calib::TPosePair> poses;
		if (folderArg.isSet()) poses = apps::readWaypointFolder(source);
		else if (driveArg.isSet()) poses = driveAndRead(driveArg.getValue(), driveOutArg.getValue(), source);
		else poses = readRawlogInput(source, truthArg.getValue());
		const auto runs = runsFromPoses(poses, options, sideArg.isSet());
		const auto result = calib::computeUmbmark(runs, options);
		apps::printUmbmark(std::cout, runs, result, options);
		if (iniArg.isSet()) apps::writeCorrectionIni(iniArg.getValue(), result, options, source);
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-umbmark: error: " << e.what() << "\n";
		return 1;
	}
}
