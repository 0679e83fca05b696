/* hslam sim: MRPT's robot interface (mrpt::nav::CRobot2NavInterface) fed by
 * our closed loop (closed_loop.h) instead of a robot, so that MRPT 2.5's
 * CReactiveNavigationSystem can drive the simulated P3-DX headless
 * (CMrptReactiveDriver). Before every navigation step the driver hands it the
 * closed loop's input (pose, latest laser scan, simulated time); MRPT reads
 * them back through the interface and leaves its (v, w) command here.
 *
 * Frames and units as MRPT documents them: pose in the world frame (m, rad);
 * velocity in the world frame (vx, vy m/s, omega rad/s), estimated from the
 * last two poses; obstacles in the CURRENT robot frame: the scan's points
 * through its sensor pose and, when `compensateScanAge`, through the robot's
 * motion since the scan was taken (the closed loop hands over the latest
 * scan, up to one laser period old: 0.1 m at MRPT's stock 1 m/s; the stock
 * config has use_delays_model = false, so MRPT would take old points as
 * current); when `useSonar`, also one point per sonar echo on its cone's
 * axis (the same laser + sonar our controller fuses, thesis 4.2.3: the laser
 * misses thin chair legs between its beams and walls seen edge-on, the sonar
 * catches them; the cone is not filled, MRPT takes points as exact);
 * timestamps and getNavigationTime() on the SIMULATED clock
 * (MRPT's own simulator interface, CRobot2NavInterfaceForSimulator_DiffDriven,
 * returns simulated time too), so the navigator's timeouts and obstacle filter
 * see the same time base as the robot. Only differential-drive commands
 * (CVehicleVelCmd_DiffDriven) are accepted, the P3-DX's kinematics. */
#pragma once

#include <hslam/sim/closed_loop.h>
#include <mrpt/nav/reactive/CRobot2NavInterface.h>
#include <mrpt/poses/CPose2D.h>

#include <deque>

namespace hslam::sim
{
class CSimRobot2NavInterface : public mrpt::nav::CRobot2NavInterface
{
   public:
	/** `clockOrigin_s`: UNIX time of the simulation start (TSimulationOptions::start_time_s),
	 * so that pose and scan timestamps share one clock. */
	CSimRobot2NavInterface(double clockOrigin_s, bool compensateScanAge = true, bool useSonar = false);

	/** The closed loop's input of this control step (the scan is copied as points). */
	void setInput(const TControlInput& in);

	/** The latest command MRPT sent (zero after stop()). */
	double commandV_mps() const { return m_v; }
	double commandW_rad_s() const { return m_w; }
	bool navigationEnded() const { return m_ended; }  //!< sendNavigationEndEvent() was called
	bool wayBlocked() const { return m_blocked; }  //!< sendWaySeemsBlockedEvent() was called
	bool navError() const { return m_error; }  //!< sendNavigationEndDueToErrorEvent() was called

	bool getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velGlobal,
								 mrpt::system::TTimeStamp& timestamp, mrpt::math::TPose2D& odometry,
								 std::string& frameId) override;
	bool changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& cmd) override;
	bool changeSpeedsNOP() override { return true; }  //!< the last command stays in force
	bool stop(bool isEmergencyStop) override;
	mrpt::kinematics::CVehicleVelCmd::Ptr getStopCmd() override;
	mrpt::kinematics::CVehicleVelCmd::Ptr getEmergencyStopCmd() override { return getStopCmd(); }
	bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp) override;
	double getNavigationTime() override { return m_t_s - m_timerStart_s; }
	void resetNavigationTimer() override { m_timerStart_s = m_t_s; }
	void sendNavigationEndEvent() override { m_ended = true; }
	void sendWaySeemsBlockedEvent() override { m_blocked = true; }
	void sendNavigationEndDueToErrorEvent() override { m_error = true; }

   private:
	mrpt::system::TTimeStamp stamp(double t_s) const;
	/** The pose at simulated time t_s, interpolated between the recorded control steps. */
	mrpt::math::TPose2D poseAt(double t_s) const;
	/** Robot at time `stamp` seen from the robot now (identity without compensation). */
	mrpt::poses::CPose2D nowFromThen(mrpt::system::TTimeStamp stamp) const;
	void addSonarEchoes(mrpt::maps::CSimplePointsMap& obstacles) const;
	double m_clockOrigin_s;
	bool m_compensate, m_useSonar;
	const mrpt::obs::CObservationRange* m_sonar = nullptr;
	std::deque<std::pair<double, mrpt::math::TPose2D>> m_history;  //!< (t_s, pose) of the last control steps
	double m_t_s = 0, m_timerStart_s = 0;
	mrpt::math::TPose2D m_pose;
	mrpt::math::TTwist2D m_velGlobal;
	bool m_havePose = false;
	const mrpt::obs::CObservation2DRangeScan* m_scan = nullptr;
	double m_v = 0, m_w = 0;
	bool m_ended = false, m_blocked = false, m_error = false;
};
}  // namespace hslam::sim
