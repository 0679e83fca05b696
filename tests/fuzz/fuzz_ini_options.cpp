/* Fuzz target: INI text through MRPT's CConfigFileMemory and our option
 * loading (range, choice and unknown-key checks): the CARMEN import, the
 * Pioneer driver and the tiled map options, plus a --set override. */
#include <hslam/common/config_overrides.h>
#include <hslam/common/options_io.h>
#include <hslam/hwdrivers/CPioneerDriver.h>
#include <hslam/io/carmen_import.h>
#include <mrpt/config/CConfigFileMemory.h>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_ini_options(const uint8_t* data, size_t size)
{
	const std::string text = asText(data, size);
	try
	{
		mrpt::config::CConfigFileMemory cfg(text);
		common::loadedOptions<io::TCarmenImportOptions>(cfg, "carmen_import");
		common::loadedOptions<hwdrivers::CPioneerDriver::TOptions>(cfg, "PIONEER");
	}
	catch (const std::exception&)  // config_error, and MRPT's own parse errors
	{
	}
	try
	{
		common::parseConfigOverride(text.substr(0, text.find('\n')));
	}
	catch (const std::exception&)
	{
	}
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_ini_options)
