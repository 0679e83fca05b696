/* hslam nav: velocity control layer (thesis 4.2.1, eq. 34; Appendix A layer3):
 * v_c = k f, f = sum over the eight ring directions of r_s cos(theta_s) (mm),
 * k = 0.034 (mm/s per mm). The thesis writes sin(theta_s) with theta measured
 * from the robot's side (its code: sin(theta_s + 90 deg)); with theta from
 * ahead that is cos(theta_s): ranges ahead count fully, side ranges not at all.
 * Ranges are clipped to max_range_mm (5000). */
#pragma once

#include <hslam/nav/virtual_sonars.h>

namespace hslam::nav
{
struct TVelocityControlOptions
{
	double gain_per_s = 0.034;  //!< eq. 34: mm/s of speed per mm of f
	double max_range_mm = 5000;  //!< sonar maximum range

	template <class V>
	void visit(V& v)
	{
		v.real("gain_per_s", gain_per_s, 0.0, 1.0);
		v.real("max_range_mm", max_range_mm, 500.0, 30000.0);
	}
};

class CVelocityControlLayer
{
   public:
	explicit CVelocityControlLayer(const TVelocityControlOptions& options = {}) : m_opts(options) {}
	/** v_c (m/s) from the ring ranges. */
	double evaluate(const std::array<TVirtualSonar, 8>& ring) const;

   private:
	TVelocityControlOptions m_opts;
};

}  // namespace hslam::nav
