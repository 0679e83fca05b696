#include <hslam/slam/COdometryCalibrationStage.h>

namespace hslam::slam
{
TOdometryIncrement COdometryCalibrationStage::correct(const TOdometryIncrement& increment) const
{
	TOdometryIncrement out = increment;
	if (increment.known) out.delta = m_calibration.correct(increment.delta);
	return out;
}

void COdometryCalibrationStage::observe(const TOdometryIncrement& uncorrected, const TPoseEstimate& estimate)
{
	if (!m_calibration.enabled()) return;
	if (!uncorrected.known || !estimate.motion_prior.empty())
		m_clean = false;
	else
		m_odometrySinceMatch = m_odometrySinceMatch + uncorrected.delta;
	const bool anchor =
		estimate.matched && estimate.match_accepted && estimate.match_quality == matching::EMatchQuality::good;
	if (!anchor) return;
	if (m_poseAtMatch && m_clean) m_calibration.observe(m_odometrySinceMatch, estimate.pose - *m_poseAtMatch);
	m_poseAtMatch = estimate.pose;
	m_odometrySinceMatch = mrpt::poses::CPose2D();
	m_clean = true;
}

}  // namespace hslam::slam
