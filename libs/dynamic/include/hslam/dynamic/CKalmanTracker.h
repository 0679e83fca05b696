/* hslam: multi-target tracker for leg and person positions (thesis 4.7.2,
 * figures 152-153, eq. 88-89, appendix H.1 dyn_det; 4.7.5/5.2 future work).
 *
 * Thesis: objects are associated frame to frame in polar coordinates after
 * predicting where a static object would appear once the robot has moved
 * (eq. 88-89 use only the forward distance dr); their radial and angular
 * velocities are estimated; an object not matched for 3 frames is dropped
 * (null counter); an object is dynamic only if it moves, and a static wall
 * piece that passed the shape test (a "ghost") is dropped.
 *
 * Here:
 *  - Every track keeps a constant-velocity Kalman filter (state x, y, vx, vy
 *    in the WORLD frame; white-noise acceleration accel_noise_mps2). Its
 *    prediction, transformed into the CURRENT sensor frame with the full
 *    sensor pose (x, y, heading), is the generalisation of eq. 88-89: a
 *    static object keeps its world position whatever the robot does, so it
 *    gets zero velocity, and a moving one its own velocity.
 *  - Association in polar coordinates of the current sensor frame, as in
 *    the thesis: |r - r_pred| <= gate_range_m and |theta - theta_pred| <=
 *    gate_bearing_deg (H.1: 10 deg), both widened by the number of missed
 *    frames; nearest pairs first (greedy, one to one). Optionally
 *    (gate_speed_mps > 0, beyond the thesis) a metric gate instead: range
 *    and cross-range distance to the prediction <= gate_speed_mps x the time
 *    since the track was last seen, the same at any range (10 deg is 0.17 m
 *    at 1 m but 0.7 m at 4 m, wide enough to hop between chair legs).
 *  - Life cycle: tentative -> dynamic once the track has moved
 *    confirm_travel_m from where it was born (seen in >= confirm_hits
 *    frames) and, if confirm_free_hits > 0, was seen that many times where
 *    the sensor had seen free space before (beyond the thesis: a track
 *    hopping between static clutter also "moves", but never into space
 *    that was free). Also beyond the thesis, two checks that what "moved"
 *    is not pose error or the robot itself: the speed must be sustained
 *    (confirm_moving_frames consecutive hits with a Kalman speed of at
 *    least confirm_speed_mps and confirm_speed_sigma standard deviations of
 *    its own covariance: pose drift moves static things slowly, people
 *    walk at 0.5-1.5 m/s), and with confirm_relative_motion the track must
 *    have moved confirm_travel_m in the sensor frame too (a part of the
 *    robot moves with it in the world but not relative to it; the rear
 *    laser of the legs data sees one). A track still short of that after ghost_after_frames hits
 *    becomes static (a ghost: never reported as dynamic, it may still turn
 *    dynamic if it starts moving); max_misses consecutive missed frames drop
 *    a track (thesis: 3).
 *  - Static-world evidence (beyond the thesis; the caller passes, per
 *    observation, since when it lies on established static structure, see
 *    CStaticEvidenceGrid): no track is confirmed on an observation on such
 *    structure, and none with more than confirm_max_static_fraction (0) of
 *    its observations on structure established before the track was born:
 *    static clutter whose track hops between neighbouring chair legs or
 *    jumps when the pose slips. (Structure established after the birth may
 *    be the track's own object standing still, which may walk off.)
 *  - Memory (beyond the thesis): a dropped dynamic track is remembered for
 *    memory_s; a new observation within memory_gate_m of where it was
 *    lost (or of its constant-velocity extrapolation) takes over its id and
 *    world travel; it is dynamic again once it passes the confirmation
 *    rule with that travel (not blindly: clutter next to a lost person or
 *    the robot's body would inherit the state), so a person reappearing after an occlusion
 *    keeps its identity. Likewise a younger track (not a ghost) near where
 *    a dropped dynamic track would be takes over its id (the observation
 *    had jumped out of the old track's gate).
 * Velocities are reported in the world frame and, as in the thesis, as
 * radial (m/s) and angular (rad/s) components seen from the sensor. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace hslam::dynamic
{
enum class ETrackState
{
	tentative,
	dynamic,
	ghost
};

const char* toString(ETrackState s);

struct TTrack
{
	int id = 0;
	ETrackState state = ETrackState::tentative;
	Eigen::Vector4d x = Eigen::Vector4d::Zero();  //!< world x, y (m), vx, vy (m/s)
	Eigen::Matrix4d P = Eigen::Matrix4d::Identity();
	double t_last_s = 0;  //!< time of the last prediction
	double t_seen_s = 0;  //!< time of the last associated observation
	int hits = 0, misses = 0;
	mrpt::math::TPoint2D birth_m;  //!< first observed world position
	double travel_m = 0;  //!< largest distance of an observation from birth_m
	int free_hits = 0;  //!< observations that came with motion evidence (see update())
	mrpt::math::TPoint2D sensor_birth_m;  //!< first observed position in the sensor frame of that scan
	double sensor_travel_m = 0;  //!< largest distance of an observation from sensor_birth_m, in the sensor frame
	int moving_frames = 0;  //!< consecutive hits with a significant speed (see confirm_speed_sigma)
	double t_birth_s = 0;  //!< time of the first observation
	bool on_static = false;  //!< last observation lies on established static structure (see update())
	int static_hits = 0;  //!< observations on static structure established before the track was born
	double leg_probability_sum = 0;  //!< sum over its observations of the classifier's leg probability (see update())
	int observation = -1;  //!< index of the observation associated in the last update, -1 if missed
	/** Polar state in the sensor frame of the last update (thesis H.1 obj[]). */
	double range_m = 0, bearing_rad = 0, v_radial_mps = 0, v_angular_radps = 0;

	mrpt::math::TPoint2D position() const { return {x[0], x[1]}; }
	double speed_mps() const { return std::hypot(x[2], x[3]); }
	double meanLegProbability() const { return hits > 0 ? leg_probability_sum / hits : 0.0; }
};

/** One detection given to CKalmanTracker::update: where it is and the
 * evidence that comes with it. The defaults ask for no evidence (thesis rule). */
struct TTrackObservation
{
	mrpt::math::TPoint2D position_m;  //!< world frame
	/** Lies where the sensor saw free space before: confirm_free_hits of these
	 * are needed before a track can be confirmed dynamic (leave true when the
	 * caller has no such evidence: the requirement is then waived). */
	bool motion_evidence = true;
	/** Time since which it lies on established static structure
	 * (CStaticEvidenceGrid; +infinity: not on it): a track is never confirmed
	 * on such an observation, nor while more than confirm_max_static_fraction
	 * of its observations lay on structure established before the track was born. */
	double static_since_s = std::numeric_limits<double>::infinity();
	/** The leg classifier's probability (CLegClassifier): a track is confirmed
	 * only while the mean over its observations is at least
	 * confirm_min_leg_probability (one scan rarely tells a leg from a chair
	 * leg; many views of the same object do). */
	double leg_probability = 1.0;
};

class CKalmanTracker
{
   public:
	struct TOptions
	{
		double gate_range_m = 0.4;  //!< polar gate, range part (H.1 uses 1.3 x robot travel)
		double gate_bearing_rad = 10.0 * M_PI / 180;  //!< polar gate, bearing part (H.1: 10 deg)
		double gate_min_cross_m = 0.25;  //!< the bearing gate never narrower than this across the beam (m)
		double gate_speed_mps = 0;  //!< > 0: metric gate instead, |dr| and cross-range <= this x time since last seen
		int max_misses = 3;  //!< thesis null counter: dropped after 3 missed frames
		double confirm_travel_m = 0.20;  //!< distance from birth that makes a track dynamic
		int confirm_hits = 2;  //!< observations needed before a track can be dynamic
		int ghost_after_frames = 5;  //!< hits after which a track that has not moved is a ghost
		double accel_noise_mps2 = 3.0;  //!< CV model process noise (walking people)
		double measurement_noise_m = 0.05;  //!< position noise of a leg/person observation
		double max_speed_mps = 3.0;  //!< initial velocity uncertainty and speed cap
		double memory_s = 2.0;  //!< how long a lost dynamic track can be re-identified
		double memory_gate_m = 0.7;  //!< re-identification radius
		int confirm_free_hits = 1;  //!< observations with motion evidence needed to confirm (0: thesis rule; waived when update() gets no evidence)
		int confirm_moving_frames = 2;  //!< consecutive hits with a significant speed needed to confirm (0: off, thesis rule)
		double confirm_speed_mps = 0.2;  //!< "significant speed": at least this fast ...
		double confirm_speed_sigma = 1.0;  //!< ... and this many standard deviations (Kalman covariance) above zero
		bool confirm_relative_motion = true;  //!< also require confirm_travel_m in the sensor frame (not attached to the robot; thesis: no)
		double confirm_max_static_fraction = 0.0;  //!< at most this share of hits on structure older than the track (0: none; 1: off)
		double confirm_min_leg_probability = 0.0;  //!< mean classifier leg probability of its observations needed to confirm (0: off)

		template <class V>
		void visit(V& v)
		{
			v.real("gate_range_m", gate_range_m, 0.01, 10.0);
			v.degrees("gate_bearing_deg", gate_bearing_rad, 0.1, 180.0);
			v.real("gate_min_cross_m", gate_min_cross_m, 0.0, 10.0);
			v.real("gate_speed_mps", gate_speed_mps, 0.0, 100.0);
			v.integer("max_misses", max_misses, 1, 1000);
			v.real("confirm_travel_m", confirm_travel_m, 0.0, 10.0);
			v.integer("confirm_hits", confirm_hits, 1, 1000);
			v.integer("ghost_after_frames", ghost_after_frames, 1, 1000);
			v.real("accel_noise_mps2", accel_noise_mps2, 0.001, 100.0);
			v.real("measurement_noise_m", measurement_noise_m, 0.001, 10.0);
			v.real("max_speed_mps", max_speed_mps, 0.01, 100.0);
			v.real("memory_s", memory_s, 0.0, 3600.0);
			v.real("memory_gate_m", memory_gate_m, 0.0, 100.0);
			v.integer("confirm_free_hits", confirm_free_hits, 0, 1000);
			v.integer("confirm_moving_frames", confirm_moving_frames, 0, 1000);
			v.real("confirm_speed_mps", confirm_speed_mps, 0.0, 100.0);
			v.real("confirm_speed_sigma", confirm_speed_sigma, 0.0, 100.0);
			v.flag("confirm_relative_motion", confirm_relative_motion);
			v.real("confirm_max_static_fraction", confirm_max_static_fraction, 0.0, 1.0);
			v.real("confirm_min_leg_probability", confirm_min_leg_probability, 0.0, 1.0);
		}
	};

	CKalmanTracker() : CKalmanTracker(TOptions()) {}
	explicit CKalmanTracker(const TOptions& options) : m_options(options) {}

	/** One frame: `observations` (world positions with their evidence, see
	 * TTrackObservation), `sensorPose` the sensor pose in the world at time
	 * `t_s` (s). Returns, per observation, the id of the track it now belongs
	 * to (new tracks are created for the rest). */
	std::vector<int> update(const std::vector<TTrackObservation>& observations, const mrpt::poses::CPose2D& sensorPose,
							double t_s);

	/** Live tracks (tentative, dynamic and ghost), after the last update. */
	const std::vector<TTrack>& tracks() const { return m_tracks; }
	const TTrack* find(int id) const;

	const TOptions& options() const { return m_options; }
	/** Number of tracks ever created (ids are 1..this). */
	int createdTracks() const { return m_nextId - 1; }
	/** Re-identifications from memory so far. */
	size_t reidentifications() const { return m_reidentified; }

   private:
	struct TMemory
	{
		TTrack track;
		double t_lost_s = 0;
	};

	void predict(TTrack& t, double t_s) const;
	void correct(TTrack& t, const mrpt::math::TPoint2D& z) const;
	bool inGate(const TTrack& t, const mrpt::math::TPoint2D& z, const mrpt::poses::CPose2D& sensorPose,
				double t_s) const;
	void updatePolar(TTrack& t, const mrpt::poses::CPose2D& sensorPose) const;
	TTrack newTrack(const mrpt::math::TPoint2D& z, const mrpt::poses::CPose2D& sensorPose, double t_s);
	void registerHit(TTrack& t, const TTrackObservation& z, const mrpt::poses::CPose2D& sensorPose) const;
	bool significantSpeed(const TTrack& t) const;
	bool meetsConfirmation(const TTrack& t) const;
	/** Greedy one-to-one association, nearest (predicted, observed) pairs
	 * first; corrects and registers the hits. Returns, per observation, its
	 * track id (-1: none) and sets `trackUsed`. */
	std::vector<int> associate(const std::vector<TTrackObservation>& observations, const mrpt::poses::CPose2D& sensorPose,
							   double t_s, std::vector<bool>& trackUsed);
	/** Missed tracks: null counter; dropped after max_misses (dynamic ones are remembered). */
	void dropMissedTracks(const std::vector<bool>& trackUsed);
	void takeOverFromMemory(double t_s, std::vector<int>& owner);
	/** The remembered track nearest to `z` (or its constant-velocity
	 * extrapolation) within memory_gate_m; m_memory.end() if none. */
	std::vector<TMemory>::iterator rememberedNear(const mrpt::math::TPoint2D& z, double t_s);
	/** A new track for an unassociated observation, or a remembered one re-identified. */
	TTrack startTrack(const TTrackObservation& z, const mrpt::poses::CPose2D& sensorPose, double t_s);

	TOptions m_options;
	std::vector<TTrack> m_tracks;
	std::vector<TMemory> m_memory;
	int m_nextId = 1;
	size_t m_reidentified = 0;
};

}  // namespace hslam::dynamic
