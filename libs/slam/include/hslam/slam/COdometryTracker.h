/* hslam: collects odometry from a rawlog (CActionRobotMovement2D increments
 * in actions/sensory-frame rawlogs, absolute CObservationOdometry readings in
 * observations-only rawlogs) and hands the pose change since the previous
 * laser scan to the pose estimator.
 *
 * A missing increment (a "ODOMETRY_GAP" comment written by our CARMEN
 * importer, or a CObservationOdometry chain that restarts) is reported as
 * unknown motion, never silently as zero motion; so is every increment of a
 * log that has no odometry at all (laser-only recordings), and the interval
 * in which the first absolute reading arrives after a scan (odometry that
 * starts late: that reading is an origin, the motion before it unknown).
 *
 * Timing ([odometry_timing], TOdometryTiming): a reading stamped t is taken
 * as the pose at t - offset_s (odometry stamped late against the laser by
 * offset_s), and with `interpolate` the increment up to a scan at t_s ends
 * at t_s exactly: the readings up to t_s are composed as they came, and of
 * the first reading after it the fraction of its interval before t_s
 * (linearly); the rest waits for the next scan. A reading after the scan is
 * only there if the caller held the scan until one came (CMappingPipeline
 * does: readingTimeAfter()). Actions (CActionRobotMovement2D) carry no
 * time and always count before the next scan. With every reading at or
 * before its scan (CARMEN imports: one per scan, same stamp) the increments
 * are those of plain composition, bit for bit. */
#pragma once

#include <hslam/calib/COdometryCorrection.h>
#include <hslam/calib/COdometryTimeOffset.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <limits>
#include <optional>

namespace hslam::slam
{
/** Robot pose change between two laser scans, in the robot frame of the first. */
struct TOdometryIncrement
{
	mrpt::poses::CPose2D delta;  //!< identity when unknown
	bool known = true;  //!< false: odometry was missing for (part of) the interval
};

/** [odometry_timing] section. */
struct TOdometryTiming
{
	/** Age of the pose a reading reports against its stamp (s): positive =
	 * odometry stamped late against the laser. */
	double offset_s = 0;
	/** End each scan's increment at the scan's time, interpolating within the
	 * reading interval around it (the scan waits for the next reading). */
	bool interpolate = true;
	/** Longest a scan (or any sensor reading) waits for the odometry reading
	 * after it (s of later data); then it is processed with what came. */
	double max_wait_s = 0.5;
	calib::TOdometryTimeOffsetOptions estimation;  //!< the offset estimated from the matches
	/** hslam-process: when the run fitted an offset, process the rawlog once
	 * more from the start with it (the outputs are the second pass's). */
	bool second_pass = true;

	template <class V>
	void visit(V& v)
	{
		v.real("offset_s", offset_s, -5.0, 5.0);
		v.flag("interpolate", interpolate);
		v.real("max_wait_s", max_wait_s, 0.0, 10.0);
		estimation.visit(v);
		v.flag("second_pass", second_pass);
	}
};

class COdometryTracker
{
   public:
	COdometryTracker() = default;
	/** With a UMBmark calibration (thesis 4.1) applied to every increment. */
	explicit COdometryTracker(const calib::TOdometryCorrection& correction, const TOdometryTiming& timing = {})
		: m_correction(correction), m_timing(timing)
	{
	}
	const TOdometryTiming& timing() const { return m_timing; }
	/** Readings from now on are taken as the pose at stamp - offset_s. */
	void setOffset(double offset_s) { m_timing.offset_s = offset_s; }
	const calib::TOdometryCorrection& correction() const { return m_correction.options(); }

	/** Prefix of the CObservationComment text that marks missing odometry
	 * (MRPT does not serialize a comment's sensorLabel, so the text carries it). */
	static constexpr const char* kGapMarker = "ODOMETRY_GAP";
	static bool isGapMarker(const mrpt::obs::CObservationComment& comment)
	{
		return comment.text.rfind(kGapMarker, 0) == 0;
	}

	void addAction(const mrpt::obs::CActionRobotMovement2D& action);
	void addOdometryObservation(const mrpt::obs::CObservationOdometry& odometry);
	/** Declares that the motion since the last scan is unknown. */
	void markGap()
	{
		m_gap = true;
		m_lastStepTime_s = -std::numeric_limits<double>::infinity();  // no reading after it is spread back over it
	}

	/** Pose change since the previous call (i.e. the previous scan); with
	 * `interpolate` and a time, up to that time (s, the scan's stamp). */
	TOdometryIncrement takeIncrement(std::optional<double> t_s = std::nullopt);
	/** What takeIncrement() would return now, without consuming it (for
	 * sensors read between scans, e.g. sonars). */
	TOdometryIncrement pendingIncrement(std::optional<double> t_s = std::nullopt) const;
	/** Whether a reading at or after `t_s` (offset applied) has come: a
	 * reading to interpolate against. Always true without absolute readings
	 * or without `interpolate` (nothing to wait for). */
	bool readingTimeAfter(double t_s) const;

   private:
	struct TStep
	{
		double t_s;  //!< the reading's time (offset applied); -inf for actions
		mrpt::poses::CPose2D delta;  //!< corrected increment since the step before
	};
	/** Composition of the pending steps up to t_s (all with no time), and
	 * how many whole steps that took; `partial` receives the fraction of the
	 * step after them that lies before t_s (identity if none). */
	mrpt::poses::CPose2D composedUpTo(std::optional<double> t_s, size_t& whole, mrpt::poses::CPose2D& partial) const;
	/** `whole` followed by the cut reading's `partial` (if any). */
	static mrpt::poses::CPose2D withPartial(const mrpt::poses::CPose2D& whole, const mrpt::poses::CPose2D& partial);

	calib::COdometryCorrection m_correction;  //!< identity unless [odometry_correction] enables it
	TOdometryTiming m_timing;
	std::deque<TStep> m_pending;  //!< increments since the last scan, in arrival order
	double m_lastStepTime_s = -std::numeric_limits<double>::infinity();  //!< of the last step taken into a scan
	double m_newestReading_s = -std::numeric_limits<double>::infinity();
	std::optional<mrpt::poses::CPose2D> m_lastAbsolute;
	bool m_gap = false;
	bool m_anyOdometry = false;  //!< false until the first odometry reading: motion unknown
	bool m_scanTaken = false;  //!< takeIncrement() was called (a scan came) at least once
};

}  // namespace hslam::slam
