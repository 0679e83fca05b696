/* hslam: shared bits of the apps' command lines. */
#pragma once

namespace hslam::common
{
/** Exit code once TCLAP's parse() returned false: it does so both after
 * printing --help / --version (success, 0) and after reporting a usage
 * error (1). */
int exitCodeAfterParseStop(int argc, char** argv);
}  // namespace hslam::common
