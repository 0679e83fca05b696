/* hslam-bench: running another program and timing it (used by the suites
 * that compare whole processes: pipeline, graph). */
#pragma once

#include <string>

namespace hslam::bench
{
/** `s` quoted for /bin/sh. */
std::string shellQuote(const std::string& s);

/** Runs `command` (stdin /dev/null, stdout + stderr to `logFile`) and returns
 * the CPU time (user + system) of the child processes in seconds; throws
 * naming the command and the log when it exits non-zero. */
double childCpuSeconds(const std::string& command, const std::string& logFile);

}  // namespace hslam::bench
