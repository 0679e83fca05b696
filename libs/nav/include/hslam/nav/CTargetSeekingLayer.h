/* hslam nav: target seeking layer (thesis 4.2.1, eq. 33; Appendix A layer0).
 * Forward part: v_t = v_max d_t / (d_t + d_half), thesis v_max = 300 mm/s,
 * d_half = 300 mm (the appendix used 500 / 500). Rotational part: the bearing
 * of the target relative to the robot heading, which subsumes the sector
 * selecting layer (it keeps only the sector nearest that bearing). The target
 * counts as reached within goal_tolerance_mm (appendix: 200 mm). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

namespace hslam::nav
{
struct TTargetSeekingOptions
{
	double max_speed_mm_s = 300;  //!< eq. 33
	double half_speed_distance_mm = 300;  //!< eq. 33
	double goal_tolerance_mm = 200;  //!< appendix A: |dx| + |dy| < 200 mm (here Euclidean)

	template <class V>
	void visit(V& v)
	{
		v.real("max_speed_mm_s", max_speed_mm_s, 10.0, 2000.0);
		v.real("half_speed_distance_mm", half_speed_distance_mm, 1.0, 10000.0);
		v.real("goal_tolerance_mm", goal_tolerance_mm, 10.0, 5000.0);
	}
};

struct TTargetSeekingOutput
{
	double v_mps = 0;  //!< eq. 33
	double bearing_rad = 0;  //!< target direction relative to the heading, (-pi, pi]
	double distance_m = 0;
	bool reached = false;
};

class CTargetSeekingLayer
{
   public:
	explicit CTargetSeekingLayer(const TTargetSeekingOptions& options = {}) : m_opts(options) {}
	TTargetSeekingOutput evaluate(const mrpt::math::TPose2D& pose, const mrpt::math::TPoint2D& target) const;
	const TTargetSeekingOptions& options() const { return m_opts; }

   private:
	TTargetSeekingOptions m_opts;
};

}  // namespace hslam::nav
