/* hslam: the one strict reader of INI files, used by every app.
 *
 * MRPT's CConfigFile / CConfigFileMemory (SimpleIni underneath) accept almost
 * anything: a binary file loads as an empty configuration, keys before the
 * first section and lines without '=' are dropped, and a repeated key or
 * section silently replaces the earlier one. Reading through here first
 * checks the text line by line and throws config_error naming the file and
 * the line for each of those, then hands the text to CConfigFileMemory, so
 * the result reads exactly as MRPT would read the file (MRPT conventions
 * kept: `[section]`, `key = value`, whole-line comments starting with ';',
 * '#' or '//', MRPT's `@define NAME VALUE`, `${NAME}`, `$eval{...}`,
 * `$env{...}` and a trailing backslash continuing a line). Section and key
 * names compare without case, as MRPT looks them up. */
#pragma once

#include <mrpt/config/CConfigFileMemory.h>

#include <string>
#include <vector>

namespace hslam::common
{
/** Reads and checks the INI file `path`; throws config_error
 * "PATH:LINE: why" for malformed content, "PATH: why" if it cannot be read. */
mrpt::config::CConfigFileMemory loadIniFile(const std::string& path);

/** Checks INI text (`name` is used in the messages, like a file name) and
 * loads it; throws config_error as loadIniFile() does. */
mrpt::config::CConfigFileMemory parseIniText(const std::string& text, const std::string& name);

/** As checkKnownSections() of options_io.h: throws config_error if `cfg`
 * has a section not in `knownSections`, the message starting with
 * "FILE:LINE: " where that section's header is in `iniFile` (the file `cfg`
 * was read from; may be empty). */
void checkKnownSectionsInFile(const mrpt::config::CConfigFileBase& cfg, const std::vector<std::string>& knownSections,
							  const std::string& iniFile);

}  // namespace hslam::common
