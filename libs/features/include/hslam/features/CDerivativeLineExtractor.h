/* hslam: the thesis' line segmentation by differentiation (4.4.2 i-ii,
 * figures 82-84, appendix C.1) with total-least-squares identification.
 *
 * Algorithm, per scan:
 *  1. Valid points only (scan_points.h); every invalid beam (flag off, NaN,
 *     <= 0, >= maxRange) ends a run, so no derivative is ever taken across
 *     one and invalid beams cannot produce corners. So does a step of more
 *     than max_point_gap_m between neighbouring points (not in the thesis:
 *     five points 0.6 m apart at grazing incidence are not a reliable wall).
 *  2. l_i = ln(r_i); second derivative by central finite differences w.r.t.
 *     the beam index, d2_i = (l_{i+k} - 2 l_i + l_{i-k}) / k with step k
 *     (thesis: k = 1), only where all three beams are in the same run.
 *     k = derivative_step_deg / beam spacing, rounded, >= 1 (2 beams at 1 deg,
 *     4 at 0.5 deg), and min_peak, given for 1 deg beams, is scaled by the
 *     beam spacing, so the method behaves alike on 181- and 361-beam scans.
 *     A straight wall gives a smooth, small d2 (d^2 ln r / dtheta^2 =
 *     1/cos^2 of the incidence angle), a corner a single-signed peak, a depth
 *     jump a +/- pair: a zero crossing.
 *  3. d2 is normalised by its largest |peak| in the scan and |d2| above
 *     peak_threshold (thesis 0.1, the "shod" array) is kept. Each cluster of
 *     kept neighbours with a sign change is a zero crossing: the segment ends
 *     before it (a jump). A cluster without one is a corner at its largest
 *     peak (the thesis' "mono peak").
 *  4. Noise filters (figure 84): neighbouring pieces whose fitted directions
 *     differ by less than merge_angle_deg (thesis 10 deg) are merged unless
 *     the distance criterion (aa + a + b)/(a + b) of eq. 56 exceeds
 *     gap_ratio (thesis 1.05): a is the extent of the first piece, b of the
 *     second, aa the gap between them, i.e. a real gap must exceed 5 % of
 *     their combined length.
 *  5. Each piece is fitted by TLS (line_fit.h, eq. 57-64); pieces with fewer
 *     than min_points points, shorter than min_length_m or with a fit RMS
 *     above max_fit_rms_m (clutter, not a wall) are dropped.
 *
 * Deviations (each because the literal method fails on real scans):
 *  - Normalising by the single largest peak lets one large depth jump (a door
 *    edge: |d2| ~ 0.5) hide every corner (a 90 deg corner gives |d2| >= 0.035
 *    per beam). The normalisation is therefore done twice: after the clusters
 *    found with the scan-wide maximum are taken out, the remaining d2 is
 *    normalised by its own maximum and searched again. An absolute floor
 *    min_peak keeps pure sensor noise from becoming peaks when a scan has no
 *    corner at all; the default step of 2 deg (k = 2 at 1 deg) halves the
 *    noise of d2 and still places corners within one beam.
 *  - The thesis code (appendix C.1) passes the first derivative through
 *    atan(57.2 d1 / max|d1|) before differentiating again; that compresses
 *    jumps but makes the threshold depend on the scan's steepest wall. Not used.
 *  - The appendix code replaced eq. 56 by "aa < 100 mm" and measured a and b
 *    with a mix of range and atan terms; here eq. 56 as printed, with
 *    Euclidean lengths and the gap aa counted beyond the normal point spacing
 *    (segment_ops.h gapCriterion), plus a collinearity check: the merged
 *    fit's RMS must stay below merge_rms_growth times the pieces' own RMS
 *    + 5 mm and below max_fit_rms_m (two parallel walls 10 cm apart pass the
 *    10 deg test and eq. 56, but are not one line; a noisy wall's pieces
 *    are). The 10 deg test is only applied where both pieces' directions are
 *    known to better than a third of it (segment_ops.h TMergeRule): the
 *    direction of a 3-point piece under 1 cm noise is uncertain by more than
 *    10 deg.
 *  - A piece whose points deviate more than split_distance_m from the chord is
 *    split further by the iterative end point rule (a corner too shallow for
 *    the derivative, e.g. < 25 deg, or one within k beams of a run end).
 *    Boundary points move to the neighbouring line if they lie closer to it.
 *  - Corner points: the thesis excludes the corner beam from both fits; here
 *    it goes to the line it fits best, so endpoints reach the corner. */
#pragma once

#include <hslam/features/CLineExtractor.h>
#include <hslam/features/scan_points.h>

#include <vector>

namespace hslam::features
{
class CDerivativeLineExtractor : public CLineExtractor
{
   public:
	struct TOptions
	{
		double peak_threshold = 0.1;  //!< kept |d2| relative to the largest peak (thesis 0.1)
		double min_peak = 0.02;  //!< absolute floor on |d2| (change of d ln r / d beam), for 1 deg beams
		double derivative_step_rad = 2.0 * M_PI / 180;  //!< finite-difference step as an angle (thesis: 1 beam = 1 deg)
		double merge_angle_rad = 10.0 * M_PI / 180;  //!< noise filter 1 (thesis 10 deg)
		double gap_ratio = 1.05;  //!< noise filter 2, eq. 56 (thesis 1.05)
		double split_distance_m = 0.05;  //!< IEP guard split of the pieces, chord distance (not in the thesis)
		double merge_rms_growth = 2.0;  //!< collinearity test of the merge (segment_ops.h TMergeRule)
		double max_fit_rms_m = 0.04;  //!< no merge may produce, and no line may have, a larger fit RMS
		double max_point_gap_m = 0.5;  //!< neighbouring points farther apart are never on one line
		int min_points = 5;  //!< points per line
		double min_length_m = 0.2;  //!< line length

		template <class V>
		void visit(V& v)
		{
			v.real("peak_threshold", peak_threshold, 0.001, 1.0);
			v.real("min_peak", min_peak, 0.0, 10.0);
			v.degrees("derivative_step_deg", derivative_step_rad, 0.1, 20.0);
			v.degrees("merge_angle_deg", merge_angle_rad, 0.0, 45.0);
			v.real("gap_ratio", gap_ratio, 1.0, 10.0);
			v.real("split_distance_m", split_distance_m, 0.001, 1.0);
			v.real("merge_rms_growth", merge_rms_growth, 1.0, 100.0);
			v.real("max_fit_rms_m", max_fit_rms_m, 0.001, 1.0);
			v.real("max_point_gap_m", max_point_gap_m, 0.01, 100.0);
			v.integer("min_points", min_points, 2, 10000);
			v.real("min_length_m", min_length_m, 0.0, 100.0);
		}
	};

	CDerivativeLineExtractor() : CDerivativeLineExtractor(TOptions()) {}
	explicit CDerivativeLineExtractor(const TOptions& options) : m_options(options) {}

	std::string name() const override { return "derivative"; }
	using CLineExtractor::extract;
	TLineSegmentList extract(const common::TRangeData& scan) const override;
	void saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const override;

	/** Steps 1-3 only: the piece boundaries of the valid points (each range
	 * starts a piece), before the noise filters. Exposed for tests and plots. */
	std::vector<TIndexRange> segmentByDerivative(const TScanPoints& points) const;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace hslam::features
