#include <hslam/slam/COdometryTracker.h>

namespace hslam::slam
{
void COdometryTracker::addAction(const mrpt::obs::CActionRobotMovement2D& action)
{
	m_anyOdometry = true;
	mrpt::poses::CPose2D change;
	action.poseChange->getMean(change);
	m_accumulated = m_accumulated + m_correction.correctIncrement(change);
}

void COdometryTracker::addOdometryObservation(const mrpt::obs::CObservationOdometry& odometry)
{
	m_anyOdometry = true;
	// The first reading is an origin, not an increment: if a scan came before
	// it (a recording whose laser driver started before the robot's), the
	// motion between that scan and this reading is unknown, not zero.
	if (!m_lastAbsolute && m_scanTaken) m_gap = true;
	if (m_lastAbsolute) m_accumulated = m_accumulated + m_correction.correctIncrement(odometry.odometry - *m_lastAbsolute);
	m_lastAbsolute = odometry.odometry;
}

TOdometryIncrement COdometryTracker::pendingIncrement() const
{
	TOdometryIncrement out;
	// A log without any odometry (laser-only recordings) says nothing about
	// motion: unknown, not zero, so the scan matcher can track the robot.
	out.known = !m_gap && m_anyOdometry;
	out.delta = out.known ? m_accumulated : mrpt::poses::CPose2D();
	return out;
}

TOdometryIncrement COdometryTracker::takeIncrement()
{
	const TOdometryIncrement out = pendingIncrement();
	m_accumulated = mrpt::poses::CPose2D();
	m_gap = false;
	m_scanTaken = true;
	return out;
}

}  // namespace hslam::slam
