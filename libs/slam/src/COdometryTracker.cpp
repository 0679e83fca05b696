#include <hslam/slam/COdometryTracker.h>

namespace hslam::slam
{
void COdometryTracker::addAction(const mrpt::obs::CActionRobotMovement2D& action)
{
	mrpt::poses::CPose2D change;
	action.poseChange->getMean(change);
	m_accumulated = m_accumulated + change;
}

void COdometryTracker::addOdometryObservation(const mrpt::obs::CObservationOdometry& odometry)
{
	if (m_lastAbsolute) m_accumulated = m_accumulated + (odometry.odometry - *m_lastAbsolute);
	m_lastAbsolute = odometry.odometry;
}

TOdometryIncrement COdometryTracker::pendingIncrement() const
{
	TOdometryIncrement out;
	out.known = !m_gap;
	out.delta = m_gap ? mrpt::poses::CPose2D() : m_accumulated;
	return out;
}

TOdometryIncrement COdometryTracker::takeIncrement()
{
	const TOdometryIncrement out = pendingIncrement();
	m_accumulated = mrpt::poses::CPose2D();
	m_gap = false;
	return out;
}

}  // namespace hslam::slam
