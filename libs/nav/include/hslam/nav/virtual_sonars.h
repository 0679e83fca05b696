/* hslam nav: the eight P3-DX front-ring directions read from the fused
 * profile, so the thesis's sonar formulas (eq. 34, figure 62) run on laser +
 * sonar ranges alike (thesis 4.2, Appendix A layer3/layer4). */
#pragma once

#include <hslam/nav/CRangeFusion.h>

#include <array>

namespace hslam::nav
{
/** Orientation of the P3-DX front sonars (deg, CCW from ahead; Aria p3dx-sh.p). */
constexpr std::array<double, 8> kPioneerSonarAngles_deg{90, 50, 30, 10, -10, -30, -50, -90};

struct TVirtualSonar
{
	double angle_rad = 0;  //!< orientation on the robot
	double range_m = 0;  //!< nearest fused range within its cone, from the robot centre
};

/** Ranges of the eight ring directions, each the minimum over a cone of `cone_rad`. */
std::array<TVirtualSonar, 8> virtualSonars(const CPolarProfile& profile, double cone_rad);

}  // namespace hslam::nav
