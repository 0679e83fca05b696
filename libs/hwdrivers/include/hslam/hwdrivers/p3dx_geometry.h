/* hslam: Pioneer P3-DX sonar ring geometry.
 *
 * Front ring (index: x mm, y mm, heading deg; robot frame, x forward, y left,
 * relative to the centre of rotation), AriaCoda params/p3dx-sh.p:
 * 0: (69, 136, 90) 1: (114, 119, 50) 2: (148, 78, 30) 3: (166, 27, 10)
 * 4: (166, -27, -10) 5: (148, -78, -30) 6: (114, -119, -50) 7: (69, -136, -90).
 * The thesis robot has the 8 front sonars (thesis section 4.1/4.3). Poses can
 * be overridden from INI as "x_m y_m yaw_deg, x_m y_m yaw_deg, ..." (',' or ';'
 * separated; ',' is safer in INI files, where " ;" starts a comment). */
#pragma once

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace hslam::hwdrivers
{
/** The P3-DX front ring, INI text form (x_m y_m yaw_deg, ...). */
inline const char* P3DX_FRONT_SONAR_POSES =
	"0.069 0.136 90, 0.114 0.119 50, 0.148 0.078 30, 0.166 0.027 10, "
	"0.166 -0.027 -10, 0.148 -0.078 -30, 0.114 -0.119 -50, 0.069 -0.136 -90";

/** Parses "x_m y_m yaw_deg, ..." into poses (yaw in rad); throws
 * std::invalid_argument naming the bad entry. */
std::vector<mrpt::math::TPose2D> parseSonarPoses(const std::string& text);

}  // namespace hslam::hwdrivers
