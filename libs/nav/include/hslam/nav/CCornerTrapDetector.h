/* hslam nav: is the robot trapped in a corner? (thesis 4.2.1: the forward
 * turning layer backs off when "trapped in a corner"; the thesis detected this
 * with a small feed-forward network trained in MATLAB on real sonar data.)
 *
 * Here a geometric rule on the fused ranges: obstacles on the left (45..90 deg) AND
 * on the right within corner_range_mm while the front itself is within
 * corner_front_mm, i.e. the robot faces the inside of a corner or a dead end
 * that a rotation in place could not clear. A rule rather than a network: the
 * thesis's training data (real sonar near real corners) is not available, the
 * rule is exact for the simulated worlds' corners and its two thresholds can be
 * read and tuned; a network trained on simulated corners would only learn this
 * same rule back. Confirmation over confirm_steps consecutive control steps
 * (appendix A: corner1 > 3 counts of 30 ms) keeps a single noisy echo from
 * triggering it. */
#pragma once

#include <hslam/nav/CRangeFusion.h>

namespace hslam::nav
{
struct TCornerTrapOptions
{
	double corner_range_mm = 700;  //!< left and right (45..90 deg) nearer than this
	double corner_front_mm = 900;  //!< and the front (+-20 deg) nearer than this
	int confirm_steps = 3;  //!< consecutive detections before the trap is reported

	template <class V>
	void visit(V& v)
	{
		v.real("corner_range_mm", corner_range_mm, 100.0, 5000.0);
		v.real("corner_front_mm", corner_front_mm, 100.0, 5000.0);
		v.integer("confirm_steps", confirm_steps, 1, 100);
	}
};

class CCornerTrapDetector
{
   public:
	explicit CCornerTrapDetector(const TCornerTrapOptions& options = {}) : m_opts(options) {}
	/** Rule on one profile (no memory). */
	bool looksLikeCorner(const CPolarProfile& profile) const;
	/** Updates the confirmation count; true once confirmed. */
	bool update(const CPolarProfile& profile);
	void reset() { m_count = 0; }

   private:
	TCornerTrapOptions m_opts;
	int m_count = 0;
};

}  // namespace hslam::nav
