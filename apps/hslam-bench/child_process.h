/* hslam-bench: running another program and timing it (used by the suites
 * that compare whole processes: pipeline, graph). */
#pragma once

#include <string>

namespace hslam::bench
{
/** `s` quoted for /bin/sh. */
std::string shellQuote(const std::string& s);

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
