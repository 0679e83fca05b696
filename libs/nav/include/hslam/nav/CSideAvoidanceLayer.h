/* hslam nav: side obstacle avoidance layer (thesis 4.2.1, figure 62;
 * Appendix A layer4). For the left (+90..+10 deg) and right ring directions,
 * S_s = r_max^0.1 - |sin theta_s| r_s^0.1 (only positive terms), summed per
 * side and normalised: p_L = S_L / (S_L + S_R), p_R = 1 - p_L; the command is
 * w = gain (p_R - p_L) (v + v_offset), turning away from the more crowded
 * side, faster when driving faster. When an obstacle is nearer than
 * side_threshold_mm on one side the layer subsumes the heading layers with an
 * immediate rotation away from that side at escape_rate_deg_s. */
#pragma once

#include <hslam/nav/virtual_sonars.h>

namespace hslam::nav
{
struct TSideAvoidanceOptions
{
	double gain_deg_per_mm = 0.3;  //!< appendix A: 1 (deg/s per mm/s); 0.3 here (see docs/nav.md)
	double speed_offset_mm_s = 50;  //!< appendix A: (v + 50)
	double max_range_mm = 5000;
	double side_threshold_mm = 400;  //!< side obstacle this near (from the robot centre): subsume
	double escape_rate_rad_s = 30.0 * M_PI / 180.0;

	template <class V>
	void visit(V& v)
	{
		v.real("gain_deg_per_mm", gain_deg_per_mm, 0.0, 10.0);
		v.real("speed_offset_mm_s", speed_offset_mm_s, 0.0, 1000.0);
		v.real("max_range_mm", max_range_mm, 500.0, 30000.0);
		v.real("side_threshold_mm", side_threshold_mm, 0.0, 2000.0);
		v.degrees("escape_rate_deg_s", escape_rate_rad_s, 1.0, 300.0);
	}
};

struct TSideAvoidanceOutput
{
	double w_rad_s = 0;
	bool subsume = false;  //!< an obstacle within side_threshold_mm: w replaces the heading layers
};

class CSideAvoidanceLayer
{
   public:
	explicit CSideAvoidanceLayer(const TSideAvoidanceOptions& options = {}) : m_opts(options) {}
	TSideAvoidanceOutput evaluate(const std::array<TVirtualSonar, 8>& ring, double v_mps) const;

   private:
	TSideAvoidanceOptions m_opts;
};

}  // namespace hslam::nav
