/* hslam: CCarmenOdometryTracker, anchor-aware odometry increments. */
#include <hslam/io/CCarmenOdometryTracker.h>

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace hslam::io
{
namespace
{
bool samePose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	return std::abs(a.x - b.x) <= kAnchorTolerance && std::abs(a.y - b.y) <= kAnchorTolerance &&
		   std::abs(mrpt::math::wrapToPi(a.phi - b.phi)) <= kAnchorTolerance;
}
}  // namespace

bool CCarmenOdometryTracker::isAnchor(const mrpt::math::TPose2D& pose) const
{
	for (const auto& candidate : m_awaitingAnchor)
		if (samePose(pose, candidate)) return true;
	return false;
}

bool CCarmenOdometryTracker::addOdometry(const mrpt::math::TPose2D& pose, double tv_mps, double rv_radps)
{
	const bool anchor = isAnchor(pose);
	const bool afterRear = m_awaitingAfterRear;
	m_awaitingAnchor.clear();
	m_awaitingAfterRear = false;
	if (anchor)
	{
		// After a front scan the increment was already closed; after a rear
		// scan the segment up to it is closed now.
		if (afterRear) closeSegment();
		m_base = mrpt::poses::CPose2D(pose);
		m_fresh = false;
		++m_anchors;
		return true;
	}
	m_lastOdom = mrpt::poses::CPose2D(pose);
	m_fresh = true;
	m_tv_mps = tv_mps;
	m_rv_radps = rv_radps;
	return false;
}

void CCarmenOdometryTracker::closeSegment()
{
	if (m_fresh && m_base && m_lastOdom)
		m_accumulated = m_accumulated + (*m_lastOdom - *m_base);
	else
		m_accumulatedKnown = false;
	m_base = m_lastOdom;
	m_fresh = false;
}

TCarmenOdometryStep CCarmenOdometryTracker::addFrontScan(const std::vector<mrpt::math::TPose2D>& scanPoses)
{
	TCarmenOdometryStep step;
	if (!m_seenFrontScan)
	{
		step.first = true;
		m_chain = m_lastOdom ? *m_lastOdom : mrpt::poses::CPose2D();
		m_base = m_lastOdom;
		m_fresh = false;
	}
	else
	{
		closeSegment();
		step.incrementKnown = m_accumulatedKnown;
		step.increment = m_accumulated;
		if (step.incrementKnown) m_chain = m_chain + m_accumulated;
	}
	m_seenFrontScan = true;
	m_accumulated = mrpt::poses::CPose2D();
	m_accumulatedKnown = true;
	step.chainPose = m_chain;
	step.hasVelocities = m_lastOdom.has_value();
	step.tv_mps = m_tv_mps;
	step.rv_radps = m_rv_radps;
	m_awaitingAnchor = scanPoses;
	m_awaitingAfterRear = false;
	return step;
}

void CCarmenOdometryTracker::addRearScan(const std::vector<mrpt::math::TPose2D>& scanPoses)
{
	m_awaitingAnchor = scanPoses;
	m_awaitingAfterRear = m_seenFrontScan;
}

}  // namespace hslam::io
