/* hslam-carmen2rawlog: converts a CARMEN log (plain or .gz) into an MRPT
 * rawlog (observations only, or actions + sensory frames with --format
 * frames) plus a TUM file of reference poses.
 * All the work is in hslam::io::convertCarmenLog (libs/io). */
#include <hslam/common/command_line.h>
#include <hslam/common/options_io.h>
#include <hslam/common/version.h>
#include <hslam/common/output_paths.h>
#include <hslam/io/carmen_import.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <iostream>
#include <string>

namespace
{
/** Command-line values go through the options' own checks (range, choices). */
hslam::io::TCarmenImportOptions optionsFrom(bool lenient, const std::string& clock, const std::string& period,
											const std::string& maxRange, const std::string& format)
{
	mrpt::config::CConfigFileMemory cfg;
	cfg.write("carmen_import", "lenient", lenient ? "true" : "false");
	cfg.write("carmen_import", "clock", clock);
	cfg.write("carmen_import", "synthetic_period_s", period);
	cfg.write("carmen_import", "max_range_m", maxRange);
	cfg.write("carmen_import", "format", format);
	hslam::io::TCarmenImportOptions options;
	hslam::common::loadOptions(options, cfg, "carmen_import");
	return options;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TCLAP::CmdLine cmd("hslam-carmen2rawlog: CARMEN log -> MRPT rawlog (observations) + TUM reference poses", ' ', hslam::common::versionText());
		TCLAP::UnlabeledValueArg<std::string> input("input", "CARMEN log (.log or .log.gz)", true, "", "IN.log[.gz]", cmd);
		TCLAP::UnlabeledValueArg<std::string> output("output", "Output rawlog (gz-compressed)", true, "", "OUT.rawlog", cmd);
		TCLAP::ValueArg<std::string> reference("", "reference", "Output TUM file with the reference poses (required)", true, "",
											   "OUT.tum", cmd);
		TCLAP::SwitchArg lenient("", "lenient", "Skip and count malformed lines instead of failing (default: off)", cmd);
		TCLAP::ValueArg<std::string> clock("", "clock", "Scan clock: auto|ipc|logger|synthetic (default: auto)", false, "auto", "CLOCK",
										   cmd);
		TCLAP::ValueArg<std::string> period("", "synthetic-period", "Synthetic clock period (s) (default: 1.0)", false, "1.0", "S", cmd);
		TCLAP::ValueArg<std::string> maxRange("", "max-range",
											  "No-return range (m); default: derived from the log", false, "0", "M", cmd);
		TCLAP::ValueArg<std::string> format("", "format",
											"Rawlog format: observations (observations only) | frames (actions + "
											"sensory frames, for MRPT's rbpf-slam)",
											false, "observations", "FORMAT", cmd);
		// MRPT's TCLAP returns false (after printing) for --help/--version and for bad arguments.
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);

		using hslam::common::refuseOutputOverInput;
		refuseOutputOverInput(output.getValue(), "output rawlog", {input.getValue()});
		refuseOutputOverInput(reference.getValue(), "--reference", {input.getValue()});
		hslam::common::refuseSameOutputs(output.getValue(), reference.getValue());
		const auto options = optionsFrom(lenient.getValue(), clock.getValue(), period.getValue(), maxRange.getValue(),
									  format.getValue());
		const auto report =
			hslam::io::convertCarmenLog(input.getValue(), output.getValue(), reference.getValue(), options);
		std::cout << hslam::io::formatCarmenImportReport(report);
		if (report.frontScans + report.rearScans + report.rawScans == 0)
		{
			// Exit code 3: ran, but the result is empty (issue 15 item 4).
			std::cerr << "hslam-carmen2rawlog: warning: '" << hslam::common::printableName(input.getValue())
					  << "' has no laser scan: the rawlog holds no scan and the reference trajectory is empty\n";
			return 3;
		}
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-carmen2rawlog: error: " << e.what() << "\n";
		return 1;
	}
}
