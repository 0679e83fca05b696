#include <hslam/slam/COdometryCalibrationStage.h>

namespace hslam::slam
{
TOdometryIncrement COdometryCalibrationStage::correct(const TOdometryIncrement& increment) const
{
	TOdometryIncrement out = increment;
	if (increment.known) out.delta = m_calibration.correct(m_scaleCheck.correct(increment.delta));
	return out;
}

void COdometryCalibrationStage::observe(const TOdometryIncrement& uncorrected, const TPoseEstimate& estimate)
{
	if (!m_calibration.enabled() && !m_scaleCheck.options().enabled) return;
	if (uncorrected.known)
		m_reportedSinceMatch = m_reportedSinceMatch + uncorrected.delta, m_scaleCheck.noteIncrement(uncorrected.delta);
	else
		m_knownSinceMatch = false;
	if (!uncorrected.known || !estimate.motion_prior.empty())
		m_clean = false;
	else
		m_odometrySinceMatch = m_odometrySinceMatch + m_scaleCheck.correct(uncorrected.delta);
	const bool anchor =
		estimate.matched && estimate.match_accepted && estimate.match_quality == matching::EMatchQuality::good;
	if (!anchor) return;
	if (m_poseAtMatch && m_knownSinceMatch) m_scaleCheck.observe(m_reportedSinceMatch, estimate.pose - *m_poseAtMatch);
	if (m_poseAtMatch && m_clean) m_calibration.observe(m_odometrySinceMatch, estimate.pose - *m_poseAtMatch);
	m_poseAtMatch = estimate.pose;
	m_odometrySinceMatch = m_reportedSinceMatch = mrpt::poses::CPose2D();
	m_clean = m_knownSinceMatch = true;
}

}  // namespace hslam::slam
