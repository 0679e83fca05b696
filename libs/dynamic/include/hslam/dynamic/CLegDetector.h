/* hslam: leg segment extraction from one 2D laser scan (thesis 4.7.1,
 * figures 147-151, appendix H.2 DynExtract and H.3 find_interv).
 *
 * Rule set (every threshold is a TOptions field / INI key):
 *  1. Segmentation (H.2): a segment starts at a valid beam nearer than
 *     max_range_m (thesis 3200 mm) and grows while the next beam is valid, its
 *     range differs from the previous one by less than max_range_jump_m
 *     (120 mm) and its point stays within max_segment_length_m (300 mm) of the
 *     segment's first point.
 *  2. Beam count (H.3 find_interv), a window derived from a leg-width
 *     RANGE [min_leg_width_m, max_leg_width_m]: at least
 *     findInterv(range of its first beam) beams, the beams the thinnest leg
 *     subtends at the FAR edge of its range band, floor(w_min / (r_band_max *
 *     dtheta)); and, if max_leg_width_m > 0, at most maxBeams(range) =
 *     ceil(w_max / (r_band_min * dtheta)) + 2 (the widest leg at the NEAR
 *     edge of the band, plus one mixed pixel at each end). The thesis table
 *     (1 deg scanner: 10 beams under 1.0 m, 8 to 1.2 m, 6 to 1.5 m, 4 to
 *     2.2 m, 3 beyond) is the lower bound with a single width 0.18 m and no
 *     upper bound (config_ini/hslam-legs-thesis.ini). One width is wrong for real legs:
 *     with 0.18 m a 12 cm leg never has enough beams beyond 1 m. The default
 *     range 0.08-0.20 m is the thesis' own leg width window (figure 150,
 *     rule 3), so the two rules agree. Derived that way the bands work for
 *     any angular resolution (0.5, 0.35, 0.25 deg ...).
 *  3. Dip shape (figure 147, H.2 vote loop): the segment stands in front of
 *     its surroundings: the beam just outside an end is farther by at least
 *     edge_jump_m (H.2: 100 mm) or returns nothing; the thesis accepts one
 *     such end ("ff[str]>1 || ff[i-1]>1"), min_dip_edges sets how many.
 *     Width (chord between the end points) in [min_width_m, max_width_m]
 *     (figure 150: 80-200 mm) and depth (largest distance of a segment point
 *     in front of the chord, i.e. towards the sensor: the bulge of the dip in
 *     the polar plot) in [min_depth_m, max_depth_m].
 *     Optionally (require_isolated, beyond the thesis) both ends must be real
 *     boundaries: a range jump, an occlusion or no return beside them, not a
 *     cut made by the 300 mm length limit inside a longer surface (the wall
 *     pieces the thesis calls ghosts, figure 163).
 *     The thesis gives "depth 50-180 mm" without a drawing we can recover
 *     (figure 147 is lost in the text); a cylinder of 0.1-0.15 m diameter
 *     seen by a laser bulges by 20-70 mm, so the default depth window is
 *     0-180 mm (only the upper bound of the thesis is kept: a lower bound
 *     of 50 mm rejects most legs seen at 0.35 deg, see docs/dynamic.md).
 *
 * Learned alternative (beyond the thesis, whose 4.7.5 names leg recognition
 * the weak point): with classifier_model set, segments are leg_tracker's
 * clusters (leg_clusters.h) and a random forest (CLegClassifier) decides;
 * a cluster is a leg candidate at leg probability >= classifier_threshold,
 * and the probability travels with it to the tracker, which confirms a
 * track only on the mean over its life (confirm_min_leg_probability).
 *
 * Deviation: the thesis ends a segment at the first beam beyond 3200 mm but
 * counts invalid (zero) readings as near; here invalid beams end a segment
 * and count as "far" for the edge test. */
#pragma once

#include <hslam/dynamic/CLegClassifier.h>
#include <hslam/dynamic/leg_clusters.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::dynamic
{
/** One leg candidate: beams [first_beam, last_beam] of the scan. Positions
 * are in the robot frame (the scan's sensorPose applied); range and bearing
 * are measured from the sensor position with robot-frame axes. */
struct TLegSegment
{
	size_t first_beam = 0, last_beam = 0;
	double x_m = 0, y_m = 0;  //!< centroid of the segment points
	double range_m = 0, bearing_rad = 0;  //!< centroid in polar form
	double width_m = 0;  //!< chord between the end points
	double depth_m = 0;  //!< bulge towards the sensor (see file comment)
	double leg_probability = 1.0;  //!< classifier's leg probability (1 with the thesis rules)
	size_t beams() const { return last_beam - first_beam + 1; }
};

/** Why a segment was not accepted (for statistics and debug images). */
enum class ELegReject
{
	accepted,
	too_few_beams,
	too_many_beams,
	no_dip_edge,
	width,
	depth,
	cut_by_length,
	classifier  //!< leg probability below classifier_threshold
};

const char* toString(ELegReject r);

struct TSegmentCandidate
{
	TLegSegment segment;
	ELegReject verdict = ELegReject::accepted;
};

class CLegDetector
{
   public:
	struct TOptions
	{
		double max_range_m = 3.2;  //!< segments start only nearer than this (H.2: 3200 mm)
		double max_segment_length_m = 0.30;  //!< H.2: 300 mm
		double max_range_jump_m = 0.12;  //!< H.2: 120 mm between neighbouring beams
		double min_leg_width_m = 0.08;  //!< thinnest leg: least beams (0.18 alone reproduces the H.3 table at 1 deg)
		double max_leg_width_m = 0.20;  //!< widest leg: most beams (0: no upper bound, thesis)
		std::string find_interv_bands_m = "1.0 1.2 1.5 2.2";  //!< band limits of H.3; last band ends at max_range_m
		int min_beams = 3;  //!< floor of find_interv (H.3: 3 beyond 2.2 m)
		double edge_jump_m = 0.10;  //!< H.2 dip vote: 100 mm
		int min_dip_edges = 1;  //!< ends that must stand in front (thesis: 1; 2 = both ends)
		double min_width_m = 0.08, max_width_m = 0.20;  //!< figure 150
		double min_depth_m = 0.0, max_depth_m = 0.18;  //!< figure 150 upper bound (see file comment)
		bool require_isolated = false;  //!< reject segments cut by the length limit (thesis: no)
		std::string classifier_model;  //!< CLegClassifier file; empty: the rules above (thesis)
		double classifier_threshold = 0.2;  //!< least leg probability of a candidate (see file comment)
		TClusterOptions clustering;  //!< segmentation with a classifier (max_range_m is set from the above)

		template <class V>
		void visit(V& v)
		{
			v.real("max_range_m", max_range_m, 0.1, 80.0);
			v.real("max_segment_length_m", max_segment_length_m, 0.01, 5.0);
			v.real("max_range_jump_m", max_range_jump_m, 0.001, 5.0);
			v.real("min_leg_width_m", min_leg_width_m, 0.01, 2.0);
			v.real("max_leg_width_m", max_leg_width_m, 0.0, 2.0);
			v.text("find_interv_bands_m", find_interv_bands_m);
			v.integer("min_beams", min_beams, 1, 1000);
			v.real("edge_jump_m", edge_jump_m, 0.0, 10.0);
			v.integer("min_dip_edges", min_dip_edges, 0, 2);
			v.real("min_width_m", min_width_m, 0.0, 5.0);
			v.real("max_width_m", max_width_m, 0.0, 5.0);
			v.real("min_depth_m", min_depth_m, -1.0, 5.0);
			v.real("max_depth_m", max_depth_m, -1.0, 5.0);
			v.flag("require_isolated", require_isolated);
			v.text("classifier_model", classifier_model);
			v.real("classifier_threshold", classifier_threshold, 0.0, 1.0);
			v.real("cluster_distance_m", clustering.cluster_distance_m, 0.001, 5.0);
			v.integer("cluster_min_points", clustering.min_points, 1, 10000);
		}
	};

	CLegDetector() : CLegDetector(TOptions()) {}
	/** Throws std::invalid_argument if find_interv_bands_m is not an
	 * increasing list of positive numbers, std::runtime_error (naming the
	 * file) if classifier_model cannot be loaded. */
	explicit CLegDetector(const TOptions& options);
	/** With a classifier already in memory (classifier_model is ignored;
	 * null: the rules). */
	CLegDetector(const TOptions& options, std::shared_ptr<const CLegClassifier> classifier);

	/** Accepted leg segments of `scan`, in beam order. */
	std::vector<TLegSegment> detect(const mrpt::obs::CObservation2DRangeScan& scan) const;

	/** Every segment of rule 1 with the verdict of rules 2-3 (debugging, statistics). */
	std::vector<TSegmentCandidate> candidates(const mrpt::obs::CObservation2DRangeScan& scan) const;

	/** find_interv (H.3): least number of beams of a leg whose first beam is
	 * at `range_m`, for a scanner with `angularStep_rad` between beams. */
	int findInterv(double range_m, double angularStep_rad) const;
	/** Most beams of a leg whose first beam is at `range_m` (upper end of the
	 * window of rule 2); INT_MAX when max_leg_width_m is 0. */
	int maxBeams(double range_m, double angularStep_rad) const;

	const TOptions& options() const { return m_options; }
	/** The classifier in use, null with the thesis rules. */
	const std::shared_ptr<const CLegClassifier>& classifier() const { return m_classifier; }

   private:
	std::vector<TSegmentCandidate> ruleCandidates(const mrpt::obs::CObservation2DRangeScan& scan) const;
	std::vector<TSegmentCandidate> classifiedCandidates(const mrpt::obs::CObservation2DRangeScan& scan) const;

	TOptions m_options;
	std::shared_ptr<const CLegClassifier> m_classifier;
	std::vector<double> m_bandLimits_m;  //!< parsed bands + max_range_m
};

/** Angle between consecutive beams of `scan` (rad). */
double angularStep(const mrpt::obs::CObservation2DRangeScan& scan);

/** Bearing of beam i in the sensor frame (rad), MRPT convention. */
double beamBearing(const mrpt::obs::CObservation2DRangeScan& scan, size_t i);

}  // namespace hslam::dynamic
