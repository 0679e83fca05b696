/* hslam: the configuration of a mapping job, loaded, checked and resolved in
 * one place for every app that runs CMappingPipeline (hslam-process through
 * CBatchProcessor, hslam-grabber --map-config). fromConfig():
 *  - reads the INI with the strict reader (common::loadIniFile: binary
 *    files, keys before any section, lines without '=', repeated keys or
 *    sections are errors naming file and line);
 *  - makes every file path absolute: relative to the INI's folder when
 *    written in the INI, to the working directory when given by --set;
 *  - applies the --set overrides;
 *  - rejects unknown sections, and unknown keys or bad values in every
 *    section, also in those the chosen methods do not read (a typo in
 *    [ukf] with method = odometry, or in [line_extraction_iep] with
 *    method = derivative, would otherwise pass unnoticed until the method
 *    changes);
 *  - loads [output].
 * The pipeline then takes `ini` (a checked CConfigFileBase) as before. */
#pragma once

#include <hslam/common/config_overrides.h>
#include <hslam/slam/batch_outputs.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <string>
#include <vector>

namespace hslam::slam
{
struct TMappingConfig
{
	mrpt::config::CConfigFileMemory ini;  //!< checked, paths absolute, overrides applied
	TOutputOptions output;  //!< [output]

	/** `iniFile` may be empty (all defaults). Throws common::config_error
	 * naming the file and line, or [section] and key. */
	static TMappingConfig fromConfig(const std::string& iniFile, const std::vector<std::string>& overrides);

	/** Sections accepted: the pipeline's and [output]. */
	static std::vector<std::string> knownSections();
	/** Keys holding file paths (resolved as said above). */
	static std::vector<common::TPathKey> pathKeys();
};

}  // namespace hslam::slam
