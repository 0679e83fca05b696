#include <hslam/common/version.h>
#include <mrpt/version.h>

#ifndef HSLAM_PROJECT_VERSION
#error "HSLAM_PROJECT_VERSION is defined by libs/common/CMakeLists.txt"
#endif

namespace hslam::common
{
std::string projectVersion() { return HSLAM_PROJECT_VERSION; }

std::string mrptBuildVersion()
{
	// MRPT_VERSION is 0xMmp (one hex digit each): 0x258 -> 2.5.8.
	return std::to_string((MRPT_VERSION >> 8) & 0xF) + "." + std::to_string((MRPT_VERSION >> 4) & 0xF) + "." +
		   std::to_string(MRPT_VERSION & 0xF);
}

std::string versionText() { return projectVersion() + " (built against MRPT " + mrptBuildVersion() + ")"; }
}  // namespace hslam::common
