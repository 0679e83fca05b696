/* hslam-bench: benchmarks that compare our components with their peers
 * (mostly MRPT's) measured in the same run. Each suite prints a readable
 * table and then key=value lines for scripts.
 *
 *   hslam-bench grid [--rawlog FILE ...] [--repetitions N]
 */
#include "bench_common.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

int main(int argc, char** argv)
{
	TCLAP::CmdLine cmd("hslam-bench: benchmark suites (grid, hwdrivers)", ' ', "0.1");
	TCLAP::UnlabeledValueArg<std::string> suite("suite", "suite to run: grid, hwdrivers", true, "", "suite", cmd);
	TCLAP::MultiArg<std::string> rawlogs("r", "rawlog",
										 "rawlog(s) with laser scans and odometry (default: MRPT's sample rawlog)",
										 false, "file", cmd);
	TCLAP::ValueArg<int> repetitions("n", "repetitions", "timed runs per measurement, best kept (default 5)", false,
									 5, "N", cmd);
	try
	{
		if (!cmd.parse(argc, argv)) return 0;  // --help or --version was printed
		std::vector<std::string> inputs = rawlogs.getValue();
		if (inputs.empty()) inputs.push_back(hslam::bench::kMrptSampleRawlog);
		if (suite.getValue() == "grid") return hslam::bench::runGridSuite(inputs, std::max(1, repetitions.getValue()));
		if (suite.getValue() == "hwdrivers") return hslam::bench::runHwdriversSuite(std::max(1, repetitions.getValue()));
		std::cerr << "hslam-bench: unknown suite '" << suite.getValue() << "' (available: grid, hwdrivers)\n";
		return 1;
	}
	catch (const TCLAP::ArgException& e)
	{
		std::cerr << "hslam-bench: " << e.error() << " (" << e.argId() << ")\n";
		return 1;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-bench: error: " << e.what() << "\n";
		return 1;
	}
}
