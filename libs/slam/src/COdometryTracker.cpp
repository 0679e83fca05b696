#include <hslam/slam/COdometryTracker.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>

namespace hslam::slam
{
void COdometryTracker::addAction(const mrpt::obs::CActionRobotMovement2D& action)
{
	m_anyOdometry = true;
	mrpt::poses::CPose2D change;
	action.poseChange->getMean(change);
	m_pending.push_back({-std::numeric_limits<double>::infinity(), m_correction.correctIncrement(change)});
}

void COdometryTracker::addOdometryObservation(const mrpt::obs::CObservationOdometry& odometry)
{
	m_anyOdometry = true;
	const double t_s = mrpt::Clock::toDouble(odometry.timestamp) - m_timing.offset_s;
	// The first reading is an origin, not an increment: if a scan came before
	// it (a recording whose laser driver started before the robot's), the
	// motion between that scan and this reading is unknown, not zero.
	if (!m_lastAbsolute && m_scanTaken) m_gap = true;
	if (m_lastAbsolute) m_pending.push_back({t_s, m_correction.correctIncrement(odometry.odometry - *m_lastAbsolute)});
	else
		m_lastStepTime_s = t_s;  // the origin's time: where the first interval starts
	m_lastAbsolute = odometry.odometry;
	m_newestReading_s = std::max(m_newestReading_s, t_s);
}

bool COdometryTracker::readingTimeAfter(double t_s) const
{
	return !m_timing.interpolate || !m_lastAbsolute || m_newestReading_s >= t_s;
}

mrpt::poses::CPose2D COdometryTracker::composedUpTo(std::optional<double> t_s, size_t& whole,
													 mrpt::poses::CPose2D& partial) const
{
	mrpt::poses::CPose2D sum;
	partial = mrpt::poses::CPose2D();
	whole = 0;
	double before_s = m_lastStepTime_s;
	const bool cut = t_s && m_timing.interpolate;
	for (; whole < m_pending.size(); ++whole)
	{
		const TStep& step = m_pending[whole];
		if (cut && step.t_s > *t_s)
		{
			// the part of this reading's interval before the scan, linearly
			const double span_s = step.t_s - before_s;
			const double f = std::isfinite(span_s) && span_s > 0 ? std::clamp((*t_s - before_s) / span_s, 0.0, 1.0) : 0.0;
			partial = mrpt::poses::CPose2D(f * step.delta.x(), f * step.delta.y(), f * step.delta.phi());
			break;
		}
		sum = whole == 0 ? step.delta : sum + step.delta;
		if (std::isfinite(step.t_s)) before_s = step.t_s;
	}
	return sum;
}

mrpt::poses::CPose2D COdometryTracker::withPartial(const mrpt::poses::CPose2D& whole, const mrpt::poses::CPose2D& partial)
{
	// composed only when a reading was cut: otherwise plain composition, bit for bit
	return partial.x() != 0 || partial.y() != 0 || partial.phi() != 0 ? whole + partial : whole;
}

TOdometryIncrement COdometryTracker::pendingIncrement(std::optional<double> t_s) const
{
	TOdometryIncrement out;
	// A log without any odometry (laser-only recordings) says nothing about
	// motion: unknown, not zero, so the scan matcher can track the robot.
	out.known = !m_gap && m_anyOdometry;
	if (!out.known) return out;
	size_t whole = 0;
	mrpt::poses::CPose2D partial;
	out.delta = withPartial(composedUpTo(t_s, whole, partial), partial);
	return out;
}

TOdometryIncrement COdometryTracker::takeIncrement(std::optional<double> t_s)
{
	TOdometryIncrement out;
	out.known = !m_gap && m_anyOdometry;  // as pendingIncrement()
	size_t whole = 0;
	mrpt::poses::CPose2D partial;
	const mrpt::poses::CPose2D composed = composedUpTo(t_s, whole, partial);
	if (out.known) out.delta = withPartial(composed, partial);
	for (size_t i = 0; i < whole; ++i)
	{
		if (std::isfinite(m_pending.front().t_s)) m_lastStepTime_s = m_pending.front().t_s;
		m_pending.pop_front();
	}
	if (!m_pending.empty() && t_s && m_timing.interpolate && m_pending.front().t_s > *t_s)
	{  // the rest of the reading the scan fell inside starts at the scan
		m_pending.front().delta = (mrpt::poses::CPose2D() - partial) + m_pending.front().delta;
		m_lastStepTime_s = std::max(m_lastStepTime_s, *t_s);
	}
	m_gap = false;
	m_scanTaken = true;
	return out;
}

}  // namespace hslam::slam
