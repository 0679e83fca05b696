/* hslam-evaluate: ATE and RPE of an estimated 2D trajectory against a
 * reference trajectory, both TUM files. Prints a table; --json also writes
 * the figures to a file. With --rawlog, also how well each trajectory
 * explains the laser scans (scan_consistency.h), which tells the
 * reference's own slips from the estimate's. Exit code 0 on success, 1 on
 * any error. */
#include <hslam/common/command_line.h>
#include <hslam/common/output_paths.h>
#include <hslam/common/parse_number.h>
#include <hslam/common/version.h>
#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/eval/evaluation_json.h>
#include <hslam/eval/evaluation_table.h>
#include <hslam/eval/scan_consistency.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <cstdio>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

namespace
{
std::string formatSeconds(double seconds)
{
	char text[32];
	std::snprintf(text, sizeof(text), "%g", seconds);
	return text;
}

double parseMaxDt_s(const std::string& text)
{
	const auto value = hslam::common::tryParseDouble(text);
	if (!value || *value < 0)
		throw std::runtime_error("--max-dt: expected a number of seconds >= 0, got '" + text + "'");
	return *value;
}

}  // namespace

int main(int argc, char** argv)
{
	try
	{
		hslam::eval::TEvaluationOptions options;
		TCLAP::CmdLine cmd(
			"Evaluates an estimated trajectory against a reference (TUM files): poses are matched by "
			"timestamp, ATE is computed after the best SE(2) alignment, RPE for consecutive poses and "
			"for poses 1 m and 5 m of reference travel apart.",
			' ', hslam::common::versionText());
		TCLAP::UnlabeledValueArg<std::string> referenceArg("reference", "Reference trajectory (TUM file)", true, "",
														   "REFERENCE.tum", cmd);
		TCLAP::UnlabeledValueArg<std::string> estimateArg("estimate", "Estimated trajectory (TUM file)", true, "",
														  "ESTIMATE.tum", cmd);
		TCLAP::ValueArg<std::string> jsonArg("", "json", "Also write the figures to this JSON file (default: none)", false, "",
											 "OUT.json", cmd);
		TCLAP::ValueArg<std::string> maxDtArg("", "max-dt",
											  "Largest timestamp difference (s) between matched poses (default " +
												  formatSeconds(options.max_dt_s) + ")",
											  false, formatSeconds(options.max_dt_s), "S", cmd);
		TCLAP::ValueArg<std::string> rawlogArg(
			"", "rawlog",
			"Also compare how well the two trajectories explain this rawlog's laser scans (consecutive scans "
			"placed at each trajectory's poses); timestamps must match the trajectories' (default: none)",
			false, "", "LOG.rawlog", cmd);
		TCLAP::ValueArg<std::string> laserArg("", "laser-label",
											  "Sensor label of the laser for --rawlog (default: the only one there is)",
											  false, "", "LABEL", cmd);
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);
		if (laserArg.isSet() && !rawlogArg.isSet()) throw std::runtime_error("--laser-label needs --rawlog");

		options.max_dt_s = parseMaxDt_s(maxDtArg.getValue());
		if (jsonArg.isSet())
			hslam::common::refuseOutputOverInput(jsonArg.getValue(), "--json", {referenceArg.getValue(), estimateArg.getValue()});
		const auto errors = hslam::eval::evaluateTumFiles(referenceArg.getValue(), estimateArg.getValue(), options);
		hslam::eval::printEvaluation(std::cout, errors);
		std::optional<hslam::eval::TScanConsistency> consistency;
		if (rawlogArg.isSet())
		{
			hslam::eval::TScanConsistencyOptions o;
			o.max_dt_s = options.max_dt_s;
			const auto scans = hslam::eval::readScanPoints(rawlogArg.getValue(), laserArg.getValue(), o.max_range_m);
			consistency = hslam::eval::compareScanConsistency(scans, hslam::common::readTumFile(referenceArg.getValue()),
															  hslam::common::readTumFile(estimateArg.getValue()), o);
			hslam::eval::printScanConsistency(std::cout, *consistency);
		}
		if (jsonArg.isSet())
		{
			hslam::eval::writeEvaluationJson(jsonArg.getValue(), errors, consistency ? &*consistency : nullptr);
			std::cout << "\nJSON written to " << jsonArg.getValue() << "\n";
		}
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-evaluate: error: " << e.what() << "\n";
		return 1;
	}
}
