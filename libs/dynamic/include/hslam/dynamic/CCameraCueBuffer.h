/* hslam: camera moving-object cues as motion evidence for leg tracks (beyond
 * the thesis: 4.8 finds the FOE but never uses the camera for dynamic objects;
 * its figures 167 b and 181 show that flow inconsistent with the ego-motion
 * marks a moving object).
 *
 * The camera branch (libs/vision moving_cues.h) reports, per image pair,
 * regions of residual flow that disagree with the FOE, each with the bearing
 * range of its image box in the robot frame. This buffer keeps the cues of
 * the last max_age_s; a laser leg whose bearing (robot frame, at the scan)
 * lies within a kept cue's range widened by margin_rad counts as motion
 * evidence for its track, like a leg standing where free space was
 * (CDynamicObjectFilter, confirm_free_hits). No robot motion between the
 * image and the scan is compensated: the margin covers the rotation of a
 * short max_age_s and the camera's offset from the robot's centre. */
#pragma once

#include <deque>
#include <vector>

namespace hslam::dynamic
{
/** One camera cue: the bearing range (rad, robot frame, CCW from x) of an image region. */
struct TCameraCue
{
	double t_s = 0;
	double bearing_min_rad = 0, bearing_max_rad = 0;
};

struct TCameraCueOptions  //!< [dynamic_objects] camera_cue_* keys
{
	bool enabled = false;  //!< camera_cue_evidence: off by default (docs/vision.md, cue vs leg tracks)
	double max_age_s = 0.3;  //!< a cue supports legs of scans up to this much later (or earlier)
	double margin_rad = 5.0 * 3.14159265358979323846 / 180;  //!< widening of the cue's bearing range

	template <class V>
	void visit(V& v)
	{
		v.flag("camera_cue_evidence", enabled);
		v.real("camera_cue_max_age_s", max_age_s, 0.0, 10.0);
		v.degrees("camera_cue_margin_deg", margin_rad, 0.0, 45.0);
	}
};

class CCameraCueBuffer
{
   public:
	explicit CCameraCueBuffer(const TCameraCueOptions& options) : m_options(options) {}

	/** Cues of one image pair (t_s of the second image); older cues are dropped. */
	void add(const std::vector<TCameraCue>& cues, double t_s);
	/** A kept cue within max_age_s of t_s covers `bearing_rad` (robot frame). */
	bool supports(double bearing_rad, double t_s) const;
	size_t size() const { return m_cues.size(); }

   private:
	TCameraCueOptions m_options;
	std::deque<TCameraCue> m_cues;
};

}  // namespace hslam::dynamic
