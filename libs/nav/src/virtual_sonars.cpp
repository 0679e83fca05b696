/* hslam nav: virtual ring sonars from the fused profile. */
#include <hslam/nav/virtual_sonars.h>

namespace hslam::nav
{
std::array<TVirtualSonar, 8> virtualSonars(const CPolarProfile& profile, double cone_rad)
{
	std::array<TVirtualSonar, 8> ring;
	for (size_t i = 0; i < ring.size(); ++i)
	{
		ring[i].angle_rad = kPioneerSonarAngles_deg[i] * M_PI / 180.0;
		ring[i].range_m = profile.minRange(ring[i].angle_rad - 0.5 * cone_rad, ring[i].angle_rad + 0.5 * cone_rad);
	}
	return ring;
}
}  // namespace hslam::nav
