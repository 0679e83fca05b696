/* hslam: Actions/SF grouping (see CSensoryFrameBuilder.h). */
#include <hslam/hwdrivers/CSensoryFrameBuilder.h>
#include <mrpt/obs/CObservationOdometry.h>

namespace hslam::hwdrivers
{
void CSensoryFrameBuilder::flush(std::vector<TPair>& out)
{
	if (!m_frame || m_frame->size() == 0) return;
	auto acts = mrpt::obs::CActionCollection::Create();
	if (m_frameActionValid)
	{
		mrpt::obs::CActionRobotMovement2D act;
		act.computeFromOdometry(m_frameAction, motionModel);
		act.timestamp = m_frameActionTime;
		acts->insert(act);
	}
	out.emplace_back(acts, m_frame);
	m_frame.reset();
	m_frameLabels.clear();
	m_frameActionValid = false;
}

void CSensoryFrameBuilder::add(const mrpt::obs::CObservation::Ptr& obs, std::vector<TPair>& out)
{
	if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs))
	{
		const auto it = m_lastOdo.find(odo->sensorLabel);
		if (it != m_lastOdo.end())
		{
			m_pending = m_pending + (odo->odometry - it->second);
			m_pendingValid = true;
		}
		m_lastOdo[odo->sensorLabel] = odo->odometry;
		m_lastOdoTime = odo->timestamp;
		return;
	}
	const bool repeat = m_frameLabels.count(obs->sensorLabel) > 0;
	const bool tooLong = m_frame && mrpt::system::timeDifference(m_frameStart, obs->timestamp) > m_maxSpan_s;
	if (m_frame && (repeat || tooLong)) flush(out);
	if (!m_frame)
	{
		m_frame = mrpt::obs::CSensoryFrame::Create();
		m_frameStart = obs->timestamp;
		m_frameAction = m_pending;
		m_frameActionValid = m_pendingValid;
		m_frameActionTime = m_lastOdoTime;
		m_pending = mrpt::poses::CPose2D();
		m_pendingValid = false;
	}
	m_frame->insert(obs);
	m_frameLabels.insert(obs->sensorLabel);
}

}  // namespace hslam::hwdrivers
