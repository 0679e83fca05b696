/* hslam-bench: benchmarks that compare our components with their peers
 * (mostly MRPT's) measured in the same run. Each suite prints a readable
 * table and then key=value lines for scripts.
 *
 *   hslam-bench grid [--rawlog FILE ...] [--repetitions N]
 *   hslam-bench lines [--rawlog FILE|CARMEN.log.gz ...] [--repetitions N]
 *   hslam-bench sonar [--repetitions N]     (simulated runs; images into ./hslam-bench-sonar/)
 *   hslam-bench sonar-batch [--data rawlog_samples]   (sonar in the batch job vs ground truth)
 *   hslam-bench legs --data DIR [--out DIR] [--config FILE]
 *   hslam-bench legs-sim [--data rawlog_samples] [--out DIR] [--config FILE]
 *   hslam-bench hwdrivers [--repetitions N]
 *   hslam-bench vision [--data rawlog_samples] [--repetitions N]   (camera branch, bench_vision.cpp)
 *   hslam-bench pipeline [-r RAWLOG ...] [-g GROUND_TRUTH ...] [-n N]   (own options: bench_pipeline.cpp)
 *   hslam-bench graph [-r RAWLOG -g GROUND_TRUTH ...] [--max-keyframes N]   (own options: bench_graph.cpp)
 *   hslam-bench nav [--pairs-per-world N] [--methods ours,mrpt_nd,...]  (own options: bench_nav.cpp)
 */
#include <hslam/common/command_line.h>
#include <hslam/common/version.h>
#include "bench_common.h"
#include "bench_vision.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <iostream>

int main(int argc, char** argv)
{
	TCLAP::CmdLine cmd("hslam-bench: benchmark suites (grid, grid-range, lines, sonar, sonar-batch, legs, legs-sim, hwdrivers, vision, pipeline, graph, nav)", ' ', hslam::common::versionText());
	TCLAP::UnlabeledValueArg<std::string> suite("suite", "suite to run: grid, grid-range, lines, sonar, sonar-batch, legs, legs-sim, hwdrivers, vision, pipeline, graph, nav (pipeline, graph, nav: hslam-bench <suite> --help)",
												true, "", "suite", cmd);
	TCLAP::MultiArg<std::string> rawlogs("r", "rawlog",
										 "rawlog(s) with laser scans and odometry (default: MRPT's sample rawlog)",
										 false, "file", cmd);
	TCLAP::ValueArg<int> repetitions("n", "repetitions", "timed runs per measurement, best kept (default 5)", false,
									 5, "N", cmd);
	TCLAP::ValueArg<std::string> data("", "data", "legs: folder laid out like ../shared/datasets/legs; legs-sim, sonar-batch, grid-range, vision: folder of simulated samples (default: ../shared/datasets/legs, rawlog_samples)", false,
									  "../shared/datasets/legs", "dir", cmd);
	TCLAP::ValueArg<std::string> out("", "out", "folder for images written by a suite (default .)", false, ".",
									 "dir", cmd);
	TCLAP::MultiArg<std::string> references("g", "ground-truth", "grid-range: reference trajectory (TUM) of each -r rawlog, in order",
											 false, "file", cmd);
	TCLAP::ValueArg<std::string> config("c", "config", "legs suites: INI whose [dynamic_objects] overrides the suite's options (default: none)",
										false, "", "file", cmd);
	try
	{
		if (argc > 1 && std::string(argv[1]) == "pipeline") return hslam::bench::runPipelineSuite(argc, argv);
		if (argc > 1 && std::string(argv[1]) == "graph") return hslam::bench::runGraphSuite(argc, argv);
		if (argc > 1 && std::string(argv[1]) == "nav") return hslam::bench::runNavSuite(argc, argv);
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);  // help, version or a parse error
		if (suite.getValue() == "lines") return hslam::bench::runLinesSuite(rawlogs.getValue(), std::max(1, repetitions.getValue()));
		if (suite.getValue() == "grid-range")
			return hslam::bench::runGridRangeSuite(data.isSet() ? data.getValue() : "rawlog_samples", rawlogs.getValue(),
												   references.getValue());
		std::vector<std::string> inputs = rawlogs.getValue();
		if (inputs.empty()) inputs.push_back(hslam::bench::kMrptSampleRawlog);
		if (suite.getValue() == "grid") return hslam::bench::runGridSuite(inputs, std::max(1, repetitions.getValue()));
		if (suite.getValue() == "sonar") return hslam::bench::runSonarSuite(std::max(1, repetitions.getValue()), "hslam-bench-sonar");
		if (suite.getValue() == "sonar-batch")
			return hslam::bench::runSonarBatchSuite(data.isSet() ? data.getValue() : "rawlog_samples");
		if (suite.getValue() == "legs") return hslam::bench::runLegsSuite(data.getValue(), out.getValue(), config.getValue());
		if (suite.getValue() == "legs-sim")
			return hslam::bench::runLegsSimSuite(data.isSet() ? data.getValue() : "rawlog_samples", out.getValue(),
												 config.getValue());
		if (suite.getValue() == "vision")
			return hslam::bench::runVisionSuite(std::max(1, repetitions.getValue()), data.isSet() ? data.getValue() : "rawlog_samples");
		if (suite.getValue() == "hwdrivers") return hslam::bench::runHwdriversSuite(std::max(1, repetitions.getValue()));
		std::cerr << "hslam-bench: unknown suite '" << suite.getValue()
				  << "' (available: grid, grid-range, lines, sonar, sonar-batch, legs, legs-sim, hwdrivers, vision, pipeline, graph, nav)\n";
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
