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
 * starts late: that reading is an origin, the motion before it unknown). */
#pragma once

#include <hslam/calib/COdometryCorrection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>

namespace hslam::slam
{
/** Robot pose change between two laser scans, in the robot frame of the first. */
struct TOdometryIncrement
{
	mrpt::poses::CPose2D delta;  //!< identity when unknown
	bool known = true;  //!< false: odometry was missing for (part of) the interval
};

class COdometryTracker
{
   public:
	COdometryTracker() = default;
	/** With a UMBmark calibration (thesis 4.1) applied to every increment. */
	explicit COdometryTracker(const calib::TOdometryCorrection& correction) : m_correction(correction) {}
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
	void markGap() { m_gap = true; }

	/** Pose change accumulated since the previous call (i.e. the previous scan). */
	TOdometryIncrement takeIncrement();
	/** What takeIncrement() would return now, without consuming it (for
	 * sensors read between scans, e.g. sonars). */
	TOdometryIncrement pendingIncrement() const;

   private:
	calib::COdometryCorrection m_correction;  //!< identity unless [odometry_correction] enables it
	mrpt::poses::CPose2D m_accumulated;
	std::optional<mrpt::poses::CPose2D> m_lastAbsolute;
	bool m_gap = false;
	bool m_anyOdometry = false;  //!< false until the first odometry reading: motion unknown
	bool m_scanTaken = false;  //!< takeIncrement() was called (a scan came) at least once
};

}  // namespace hslam::slam
