/* hslam: dynamic object filter for mapping (thesis 4.7; 4.7.5 and 5.2
 * future work): per scan, leg segments (CLegDetector) -> leg tracks ->
 * pairs of legs -> person tracks (both CKalmanTracker), and the beams that
 * hit a confirmed dynamic object, which the grid inserter then does not mark
 * occupied (their free part still clears cells).
 *
 *  - Legs of one person: detections at most pair_max_distance_m apart are
 *    paired greedily, nearest first (Kim et al. [20] pair legs; the thesis
 *    does not). (Letting person tracks claim legs around their prediction
 *    first was tried and gave more identity switches on the simulated lab.) A pair gives one person observation at its midpoint, an
 *    unpaired leg one at its own position, so a person stays tracked while
 *    one leg is hidden behind the other or swinging.
 *  - Motion evidence (beyond the thesis): the filter keeps its own occupancy
 *    grid of what the sensor has seen (free_space_resolution_m, beams of
 *    dynamic objects not marked occupied). A leg lies "where free space was"
 *    if the cell free_space_behind_m behind its centroid along the beam (the
 *    inside of the leg) was observed with occupancy below
 *    free_space_threshold before this scan. A static object never is: the
 *    space behind it is its own body or its shadow. The trackers need
 *    confirm_free_hits such observations to confirm a track, so a track
 *    hopping between static clutter (chair legs seen from a moving robot)
 *    is not confirmed although it "moves".
 *  - Static-world evidence (beyond the thesis, CStaticEvidenceGrid): a
 *    short-memory 5 cm world grid counts in how many scans, over how long,
 *    each cell was hit. A leg within static_radius_m of a cell hit in
 *    static_min_scans scans over static_min_span_s without gaps longer than
 *    static_max_gap_s (longer than a walking foot is planted) lies on static
 *    structure; no leg or person track is confirmed dynamic on such an
 *    observation, nor ever after one on structure established before the
 *    track was born (confirm_max_static_fraction = 0; a person observation
 *    is on structure when all its legs are): a track hopping between chair
 *    legs, or jumping by a pose error, still sits on furniture seen for
 *    seconds.
 *  - A detection is dynamic if its leg track or its person track is dynamic.
 *    With person_needs_dynamic_leg (beyond the thesis) a person track needs,
 *    as its motion evidence, an observation whose leg is on a leg track
 *    confirmed dynamic itself: the midpoint of two static chair legs jumps
 *    whenever the pairing changes (pair <-> single leg) and would "move".
 *  - Beam mask: the beams of dynamic detections (plus mask_margin_beams on
 *    each side: the mixed pixels at a leg's edges), and every beam ending
 *    in a person-sized disc around a dynamic person track (radius
 *    mask_radius_m = half the pairing distance + half the widest leg, plus
 *    mask_sigma standard deviations of the track position), also one missed in this
 *    frame (its Kalman prediction), which covers legs that merged into a
 *    blob the detector rejects.
 *  - Late exclusion (the "clear previously inserted cells"): a track
 *    needs a few scans to be confirmed, and the beams that hit it meanwhile
 *    were inserted as occupied. The filter keeps those beams (scan, beam)
 *    per person track (its leg segments, and for a tentative person the
 *    beams ending within mask_radius_m of it: what the mask would have
 *    covered; at most retro_clear_max_points) and hands them over once the
 *    track is confirmed (retro_clear_beams), so the map can take back
 *    exactly the occupied updates those beams made (slam's
 *    CDynamicMappingStage; the filter knows nothing of the laser model).
 * No file I/O: see dynamic_outputs.h for the CSV rows and debug images. */
#pragma once

#include <hslam/common/range_data.h>
#include <hslam/dynamic/CCameraCueBuffer.h>
#include <hslam/dynamic/CKalmanTracker.h>
#include <hslam/dynamic/CLegDetector.h>
#include <hslam/dynamic/CStaticEvidenceGrid.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/CTiledOccupancyGrid.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <limits>
#include <map>
#include <vector>

namespace hslam::dynamic
{
/** A beam of an earlier scan; `scan` counts the scans the filter processed
 * (0 = its first). */
struct TBeamRef
{
	size_t scan = 0;
	size_t beam = 0;
};

/** One accepted leg segment of a scan and what the filter made of it. */
struct TLegObservation
{
	TLegSegment segment;  //!< robot frame
	int leg_track = 0;  //!< id of its leg track
	int person_track = 0;  //!< id of its person track
	bool is_dynamic = false;  //!< its leg track or its person track is dynamic
	bool in_free_space = false;  //!< motion evidence (see file comment; includes camera cues)
	bool camera_cue = false;  //!< a camera cue covers it (always false unless camera_cue_evidence)
	/** On static structure established since (+inf: not; see file comment). */
	double static_since_s = std::numeric_limits<double>::infinity();
};

/** Everything the filter knows after one scan. */
struct TDynamicFrame
{
	size_t scan_index = 0;  //!< scans processed before this one
	double t_s = 0;
	mrpt::poses::CPose2D robot_pose;  //!< robot pose in the world at the scan
	std::vector<TLegObservation> legs;  //!< accepted leg segments, with their tracks and evidence
	std::vector<bool> beam_is_dynamic;  //!< per beam: hits a confirmed dynamic object
	/** Earlier beams that hit a track confirmed now (see file comment). */
	std::vector<TBeamRef> retro_clear_beams;
	/** The oldest scan a later retro_clear_beams can still name (scan_index + 1: none). */
	size_t pending_since_scan = 0;
	std::vector<TTrack> leg_tracks, person_tracks;  //!< live tracks after this scan
	size_t dynamicBeams() const;
};

class CDynamicObjectFilter
{
   public:
	struct TOptions
	{
		bool enabled = true;  //!< used by the mapping pipeline (switch for comparisons)
		bool exclude_from_matching = true;  //!< pipeline: beams on predicted dynamic person tracks are not matched
		bool exclude_legs_from_matching = false;  //!< ...and those on single dynamic leg tracks
		CLegDetector::TOptions detector;
		CKalmanTracker::TOptions tracker;  //!< shared by leg and person tracks
		double pair_max_distance_m = 0.6;  //!< two legs of one person (step length)
		bool person_needs_dynamic_leg = true;  //!< a person is confirmed only with a leg confirmed dynamic itself
		double mask_radius_m = 0.40;  //!< person disc: half the pairing distance + half the widest leg (0.3 + 0.1 m)
		double mask_sigma = 3.0;  //!< ... widened by this many standard deviations of the track's Kalman position
		int mask_margin_beams = 1;  //!< extra beams masked on each side of a dynamic leg
		double free_space_resolution_m = 0.1;  //!< cell side of the filter's own grid
		double free_space_max_range_m = 8.0;  //!< beams inserted into it up to this range
		double free_space_behind_m = 0.08;  //!< where the inside of a leg is checked
		double free_space_threshold = 0.4;  //!< occupancy below this = seen free
		int retro_clear_max_points = 300;  //!< beams kept per unconfirmed person track (0: off)
		bool static_evidence = true;  //!< veto confirmation on established static structure
		CStaticEvidenceGrid::TOptions static_grid;  //!< its grid (static_* keys)
		TCameraCueOptions camera_cues;  //!< camera moving-object cues as motion evidence (CCameraCueBuffer.h)

		template <class V>
		void visit(V& v)
		{
			v.flag("enabled", enabled);
			v.flag("exclude_from_matching", exclude_from_matching);
			v.flag("exclude_legs_from_matching", exclude_legs_from_matching);
			detector.visit(v);
			tracker.visit(v);
			v.real("pair_max_distance_m", pair_max_distance_m, 0.0, 5.0);
			v.flag("person_needs_dynamic_leg", person_needs_dynamic_leg);
			v.real("mask_radius_m", mask_radius_m, 0.0, 5.0);
			v.real("mask_sigma", mask_sigma, 0.0, 10.0);
			v.integer("mask_margin_beams", mask_margin_beams, 0, 100);
			v.real("free_space_resolution_m", free_space_resolution_m, 0.01, 1.0);
			v.real("free_space_max_range_m", free_space_max_range_m, 0.1, 100.0);
			v.real("free_space_behind_m", free_space_behind_m, 0.0, 1.0);
			v.real("free_space_threshold", free_space_threshold, 0.01, 0.5);
			v.integer("retro_clear_max_points", retro_clear_max_points, 0, 100000);
			v.flag("static_evidence", static_evidence);
			v.real("static_resolution_m", static_grid.resolution_m, 0.01, 1.0);
			v.real("static_radius_m", static_grid.radius_m, 0.0, 1.0);
			v.integer("static_min_scans", static_grid.min_scans, 1, 100000);
			v.real("static_min_span_s", static_grid.min_span_s, 0.0, 3600.0);
			v.real("static_max_gap_s", static_grid.max_gap_s, 0.0, 3600.0);
			v.real("static_memory_s", static_grid.memory_s, 0.1, 3600.0);
			camera_cues.visit(v);
		}
	};

	CDynamicObjectFilter() : CDynamicObjectFilter(TOptions()) {}
	/** Throws what CLegDetector's constructor throws (bad bands, a
	 * classifier_model that cannot be loaded). */
	explicit CDynamicObjectFilter(const TOptions& options);
	/** With a leg classifier in memory (detector.classifier_model ignored). */
	CDynamicObjectFilter(const TOptions& options, std::shared_ptr<const CLegClassifier> classifier);

	/** Processes one scan taken with the robot at `robotPose` (world) at
	 * time `t_s` (s, increasing). */
	const TDynamicFrame& process(const mrpt::obs::CObservation2DRangeScan& scan,
								 const mrpt::poses::CPose2D& robotPose, double t_s);

	/** Beams of `scan` ending where a leg or person track confirmed dynamic
	 * is predicted at `t_s` (constant velocity from its Kalman state), for the
	 * robot at `predictedPose`: what scan matching must leave out (thesis
	 * figure 55 feeds the dynamic filter before the landmarks). Causal: it
	 * uses only the tracks of earlier scans. The disc is the mask radius plus
	 * `poseMargin_m` for the uncertainty of the predicted robot pose. */
	std::vector<bool> predictedDynamicBeams(const common::TRangeData& scan, const mrpt::poses::CPose2D& predictedPose,
											double t_s, double poseMargin_m) const;

	/** Camera cues of an image pair taken at `t_s` (used only with
	 * camera_cue_evidence): a leg of a later scan within a cue's bearing
	 * range counts as motion evidence (CCameraCueBuffer.h). */
	void addCameraCues(const std::vector<TCameraCue>& cues, double t_s) { m_cues.add(cues, t_s); }

	const TDynamicFrame& lastFrame() const { return m_frame; }
	const CKalmanTracker& legTracker() const { return m_legs; }
	const CKalmanTracker& personTracker() const { return m_persons; }
	const CLegDetector& detector() const { return m_detector; }
	const TOptions& options() const { return m_options; }

   private:
	/** Person observations (world positions) and, per leg, the observation it belongs to. */
	void pairLegs(const std::vector<mrpt::math::TPoint2D>& legsWorld, std::vector<TTrackObservation>& persons,
				  std::vector<int>& personOfLeg) const;
	/** Per leg of m_frame: its tracker observation (world position, free-space
	 * and static-world evidence, classifier probability). */
	std::vector<TTrackObservation> legObservations(const std::vector<mrpt::math::TPoint2D>& legsWorld,
												   const mrpt::poses::CPose2D& sensorPose, double t_s, bool useEvidence);
	void buildMask(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose);
	void collectLateExclusions(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robotPose);
	/** Pairs this scan's legs into people, updates the person tracker with
	 * their evidence, and fills person_track and is_dynamic of m_frame's legs. */
	void updatePersonTracks(const std::vector<mrpt::math::TPoint2D>& legsWorld, const mrpt::poses::CPose2D& sensorPose,
							double t_s, bool useEvidence);
	/** Radius of the disc around person track `t` whose beams are masked. */
	double maskRadius(const TTrack& t) const;
	bool seenFreeBefore(const mrpt::math::TPoint2D& legWorld, const mrpt::poses::CPose2D& sensorPose) const;
	/** Legs covered by a camera cue get motion evidence (camera_cue, in_free_space). */
	void markCameraCueEvidence(double t_s);

	TOptions m_options;
	CLegDetector m_detector;
	CKalmanTracker m_legs, m_persons;
	maps::CTiledOccupancyGrid m_seen;  //!< what the sensor has seen (motion evidence)
	maps::CLaserGridInserter m_seenInserter;
	CStaticEvidenceGrid m_static;  //!< static-world evidence (see file comment)
	CCameraCueBuffer m_cues;  //!< recent camera cues (camera_cue_evidence)
	std::map<int, std::vector<TBeamRef>> m_pendingHits;  //!< person track id -> its beams, oldest first
	size_t m_scans = 0;  //!< scans processed
	TDynamicFrame m_frame;
};

}  // namespace hslam::dynamic
