/* hslam-bench: running another program and timing it (used by the suites
 * that compare whole processes: pipeline, graph). */
#pragma once

#include <string>
#include <vector>

namespace hslam::bench
{
/** `s` quoted for /bin/sh. */
std::string shellQuote(const std::string& s);

/** The hslam-process configuration a suite runs: the INI and the `--set
 * SECTION.KEY=VALUE` overrides given to the bench, checked here as
 * hslam-process would check them (unknown section or key, bad value: throws
 * naming it) so a typo fails before minutes of runs. */
struct TProcessConfig
{
	std::string ini;  //!< absolute path
	std::vector<std::string> overrides;
	static TProcessConfig checked(const std::string& ini, const std::vector<std::string>& overrides);
	/** " -c 'INI' --set 'A.B=C' ..." for a command line. */
	std::string arguments() const;
};

/** A child's CPU time (user + system, all its threads) and wall time, s. */
struct TChildTimes
{
	double cpu_s = 0, wall_s = 0;
};

/** Runs `command` (stdin /dev/null, stdout + stderr to `logFile`) and returns
 * its CPU and wall time; throws naming the command and the log when it exits
 * non-zero. */
TChildTimes runTimedChild(const std::string& command, const std::string& logFile);

/** runTimedChild()'s CPU seconds. */
double childCpuSeconds(const std::string& command, const std::string& logFile);

}  // namespace hslam::bench
