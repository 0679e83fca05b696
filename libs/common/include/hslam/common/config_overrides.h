/* hslam: command-line overrides of INI values, `--set SECTION.KEY=VALUE`. */
#pragma once

#include <mrpt/config/CConfigFileMemory.h>

#include <string>
#include <vector>

namespace hslam::common
{
struct TConfigOverride
{
	std::string section, key, value;
};

/** Parses "SECTION.KEY=VALUE"; throws config_error naming the bad text. */
TConfigOverride parseConfigOverride(const std::string& text);

/** A key whose value is a file path. */
struct TPathKey
{
	std::string section, key;
};

/** Loads `iniFile` with the strict reader (loadIniFile(); empty name: no
 * file, all defaults), then applies the overrides in order. Every non-empty
 * value of `pathKeys` becomes an absolute path: one written in the INI file
 * is taken relative to the INI's folder (never the working directory), one
 * given in an override relative to the working directory, as any path on a
 * command line. Throws config_error naming the file and line, or the bad
 * override. */
mrpt::config::CConfigFileMemory loadConfigWithOverrides(const std::string& iniFile,
														const std::vector<std::string>& overrides,
														const std::vector<TPathKey>& pathKeys = {});

}  // namespace hslam::common
