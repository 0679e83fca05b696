/* hslam: data association of line features between two consecutive scans
 * (thesis 4.4.2 iii, figures 89-90).
 *
 * The thesis pairs lines whose lengths differ by less than 5 % ("the ratio of
 * their lengths minus one") and whose position in the sequential scan agrees.
 * Position is made explicit here: each line of the previous scan is moved into
 * the current robot frame with the odometry prediction, and must then agree
 * with the current line in normal angle and normal distance within gates that
 * widen with the odometry uncertainty. Each line is used in at most one pair
 * (greedy, lowest cost first). */
#pragma once

#include <hslam/features/line_segment.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::matching
{
struct TLinePairingOptions
{
	/** Thesis: |len1/len2 - 1| < 0.05, for 0.1 m steps. Walls cut by occlusion
	 * or by the field of view change length with motion; at the 1 m steps of
	 * the real logs 5 % left 85 % of the scans without any pair (aces: 371 of
	 * 439 failed), so the default is 0.3 and pairs must also overlap. */
	double max_length_ratio_diff = 0.3;
	double max_angle_diff_rad = 20.0 * M_PI / 180.0;  //!< gate on the predicted normal angle
	double max_rho_diff_m = 0.5;  //!< gate on the predicted normal distance
	double min_line_length_m = 0.3;  //!< shorter lines are too unstable to pair

	template <class V>
	void visit(V& v)
	{
		v.real("max_length_ratio_diff", max_length_ratio_diff, 0.0, 10.0);
		v.degrees("max_angle_diff_deg", max_angle_diff_rad, 0.1, 90.0);
		v.real("max_rho_diff_m", max_rho_diff_m, 0.01, 10.0);
		v.real("min_line_length_m", min_line_length_m, 0.0, 10.0);
	}
};

struct TLinePair
{
	size_t previous = 0;  //!< index in the previous scan's lines
	size_t current = 0;  //!< index in the current scan's lines
	double cost = 0;  //!< normalised disagreement with the prediction (lower is better)
};

/** The previous line expressed in the current robot frame, given the pose of
 * the current frame in the previous one: alpha' = alpha - phi,
 * rho' = rho - n . t (normal form, so any orientation works). */
features::TLineSegment predictLineInCurrentFrame(const features::TLineSegment& previousLine,
												 const mrpt::poses::CPose2D& currentInPrevious);

std::vector<TLinePair> pairLines(const features::TLineSegmentList& previous, const features::TLineSegmentList& current,
								 const mrpt::poses::CPose2D& predictedCurrentInPrevious,
								 const TLinePairingOptions& options);

}  // namespace hslam::matching
