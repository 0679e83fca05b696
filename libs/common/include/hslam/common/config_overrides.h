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

/** Loads an INI file into memory (throws config_error naming the file if it
 * cannot be read) and applies the overrides in order. */
mrpt::config::CConfigFileMemory loadConfigWithOverrides(
	const std::string& iniFile, const std::vector<std::string>& overrides);

}  // namespace hslam::common
