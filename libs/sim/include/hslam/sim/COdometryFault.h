/* hslam sim: odometry faults of real recordings (issue 12's failure classes),
 * applied to what the simulated Pioneer REPORTS, never to how it moves.
 *
 *   fault = freeze  the wheel readings stop changing (or creep: only
 *                   fault_motion_scale of every encoder increment is still
 *                   reported) while the robot keeps moving; readings keep
 *                   coming, so a reader sees confident zero motion. From
 *                   fault_start_s for fault_duration_s (0 = to the end: a
 *                   "laser only" log whose odometry is nearly constant).
 *   fault = drop    no odometry readings at all during the window (the sink
 *                   is told, so a writer can mark the gap as our CARMEN
 *                   importer does with an ODOMETRY_GAP comment).
 *   fault = lag     each reading reports the encoder pose of fault_lag_s
 *                   earlier (odometry stamped late against the laser, as in
 *                   real logs whose two clocks disagree: at a fast turn the
 *                   step between two scans misses much of the rotation and
 *                   the next step has it). The window's motion is not lost.
 * With freeze and drop the motion of the window is lost for good: after the window
 * the readings continue from the last reported pose with the new encoder
 * increments (a jump against the truth), as the CARMEN importer's odometry
 * chain does across a gap. Deterministic (no random numbers). With
 * fault = none the reported pose is the encoder pose itself, bit for bit. */
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/math/TTwist2D.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>
#include <string>
#include <utility>

namespace hslam::sim
{
struct TOdometryFaultOptions  //!< [odometry] fault_* keys
{
	std::string fault = "none";  //!< none | freeze | drop
	double fault_start_s = 0;  //!< elapsed time the fault begins (s)
	double fault_duration_s = 0;  //!< length of the fault (s); 0 = until the end of the run
	double fault_motion_scale = 0;  //!< freeze: fraction of each encoder increment still reported (0 = frozen)
	double fault_lag_s = 0;  //!< lag: age of the encoder pose each reading reports (s)

	template <class V>
	void visit(V& v)
	{
		v.choice("fault", fault, {"none", "freeze", "drop", "lag"});
		v.real("fault_start_s", fault_start_s, 0.0, 1e6);
		v.real("fault_duration_s", fault_duration_s, 0.0, 1e6);
		v.real("fault_motion_scale", fault_motion_scale, 0.0, 1.0);
		v.real("fault_lag_s", fault_lag_s, 0.0, 10.0);
	}
};

class COdometryFault
{
   public:
	COdometryFault(const TOdometryFaultOptions& options, const mrpt::math::TPose2D& start);

	/** Called after every physics step with the encoder (dead-reckoning) pose
	 * at elapsed time `elapsed_s`. */
	void update(double elapsed_s, const mrpt::math::TPose2D& encoderPose);
	/** The pose the odometry reports now. */
	mrpt::math::TPose2D reportedPose() const { return m_reported.asTPose(); }
	/** The velocity the odometry reports for the encoder velocity `encoder`
	 * (scaled by fault_motion_scale while frozen). */
	mrpt::math::TTwist2D reportedVelocity(double elapsed_s, const mrpt::math::TTwist2D& encoder) const;
	/** True while the fault is in effect at `elapsed_s`. */
	bool active(double elapsed_s) const;
	/** True while fault = drop is in effect: no reading is sent. */
	bool readingsDropped(double elapsed_s) const { return m_opts.fault == "drop" && active(elapsed_s); }

   private:
	TOdometryFaultOptions m_opts;
	mrpt::poses::CPose2D m_reported, m_lastEncoder;
	mrpt::poses::CPose2D m_reportedFromEncoder;  //!< after a fault: reported = this (+) encoder
	bool m_faultSeen = false;
	std::deque<std::pair<double, mrpt::poses::CPose2D>> m_history;  //!< lag: encoder poses of the last fault_lag_s
};

}  // namespace hslam::sim
