/* hslam-umbmark: printing a UMBmark result and writing it as the INI section
 * [odometry_correction] that the simulator, the Pioneer driver and the batch
 * job apply (calib::TOdometryCorrection). */
#pragma once

#include <hslam/calib/umbmark.h>

#include <ostream>
#include <string>

namespace hslam::apps
{
/** Per-run errors, centres of gravity, alpha, beta, R, Ed, Eb, factors, E_max,syst. */
void printUmbmark(std::ostream& out, const std::vector<calib::TUmbmarkEndpoint>& runs,
				  const calib::TUmbmarkResult& result, const calib::TUmbmarkOptions& options);

/** The correction section (every key commented); throws if `path` exists or cannot be written. */
void writeCorrectionIni(const std::string& path, const calib::TUmbmarkResult& result,
						const calib::TUmbmarkOptions& options, const std::string& source);

}  // namespace hslam::apps
