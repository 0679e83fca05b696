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

/** A file path in [section] key that is relative is taken relative to the
 * folder of `iniFile` when the file exists there (so an INI can name files
 * beside it), else as given (relative to the working directory); the value
 * in `cfg` is rewritten accordingly. Empty values are left alone. */
void resolvePathNextToIni(mrpt::config::CConfigFileMemory& cfg, const std::string& section, const std::string& key,
						  const std::string& iniFile);

}  // namespace hslam::common
