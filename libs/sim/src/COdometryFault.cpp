/* hslam sim: COdometryFault (frozen, missing or late odometry readings). */
#include <hslam/sim/COdometryFault.h>

namespace hslam::sim
{
COdometryFault::COdometryFault(const TOdometryFaultOptions& options, const mrpt::math::TPose2D& start)
	: m_opts(options), m_reported(start), m_lastEncoder(start)
{
}

bool COdometryFault::active(double elapsed_s) const
{
	if (m_opts.fault == "none" || elapsed_s < m_opts.fault_start_s) return false;
	return m_opts.fault_duration_s <= 0 || elapsed_s < m_opts.fault_start_s + m_opts.fault_duration_s;
}

mrpt::math::TTwist2D COdometryFault::reportedVelocity(double elapsed_s, const mrpt::math::TTwist2D& encoder) const
{
	if (!active(elapsed_s) || m_opts.fault == "lag") return encoder;  // lag: the velocity is not what is tested
	const double s = m_opts.fault_motion_scale;
	return mrpt::math::TTwist2D{s * encoder.vx, s * encoder.vy, s * encoder.omega};
}

void COdometryFault::update(double elapsed_s, const mrpt::math::TPose2D& encoderPose)
{
	const mrpt::poses::CPose2D encoder(encoderPose);
	if (m_opts.fault == "lag")
	{  // the newest stored pose at least fault_lag_s old (the first one before that)
		m_history.emplace_back(elapsed_s, encoder);
		while (m_history.size() > 1 && m_history[1].first <= elapsed_s - m_opts.fault_lag_s) m_history.pop_front();
		m_reported = active(elapsed_s) ? m_history.front().second : encoder;
		m_lastEncoder = encoder;
		return;
	}
	if (active(elapsed_s))
	{
		m_faultSeen = true;
		if (m_opts.fault == "freeze" && m_opts.fault_motion_scale > 0)
		{
			const mrpt::poses::CPose2D step = encoder - m_lastEncoder;  // in the previous encoder frame
			const double s = m_opts.fault_motion_scale;
			m_reported = m_reported + mrpt::poses::CPose2D(s * step.x(), s * step.y(), s * step.phi());
		}
		// Held (or creeping) reading: after the window the readings continue from here.
		m_reportedFromEncoder = m_reported + (mrpt::poses::CPose2D() - encoder);
	}
	else if (m_faultSeen)
		m_reported = m_reportedFromEncoder + encoder;
	else
		m_reported = encoder;  // no fault yet: exactly the encoder pose
	m_lastEncoder = encoder;
}

}  // namespace hslam::sim
