/* hslam: the version text every app prints for --version. */
#pragma once

#include <string>

namespace hslam::common
{
/** The project version (CMake project(VERSION)), e.g. "0.1.0". */
std::string projectVersion();

/** The MRPT version the project was compiled against, e.g. "2.5.8". */
std::string mrptBuildVersion();

/** "0.1.0 (built against MRPT 2.5.8)": the version argument of the apps'
 * TCLAP::CmdLine. */
std::string versionText();
}  // namespace hslam::common
