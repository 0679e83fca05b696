/* hslam: where an app finds its shipped data (INI files, leg model, samples).
 *
 * Installed layout (docs/install.md):   <prefix>/bin/<app>
 *                                       <prefix>/share/hslam/config_ini/...
 * The build tree mirrors it: build/bin/<app> and build/share/hslam/config_ini
 * (a link to the source tree's config_ini, made by CMake). The data folder is
 * found from the executable's own location (/proc/self/exe), never from the
 * working directory, so an installed or unpacked prefix works from anywhere. */
#pragma once

#include <filesystem>
#include <string>

namespace hslam::common
{
/** Folder of the running executable (resolved through /proc/self/exe). */
std::filesystem::path executableDir();

/** <prefix>/share/hslam for the running executable (may not exist). */
std::filesystem::path dataDir();

/** The default pipeline INI: dataDir()/config_ini/hslam-default.ini. */
std::string defaultConfigFile();

/** `path` itself when it exists (or is absolute); otherwise, for a relative
 * path such as "config_ini/sim-lab.ini", dataDir()/path when that exists;
 * otherwise `path` unchanged (the caller's open then names it). */
std::string resolveDataFile(const std::string& path);
}  // namespace hslam::common
