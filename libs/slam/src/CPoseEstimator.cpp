#include <hslam/slam/CPoseEstimator.h>

#include <stdexcept>

namespace hslam::slam
{
std::unique_ptr<CPoseEstimator> createPoseEstimator(const TPoseEstimationOptions& options,
													const mrpt::config::CConfigFileBase& /*cfg*/)
{
	if (options.method == "odometry") return std::make_unique<COdometryPoseEstimator>();
	throw std::invalid_argument("[pose_estimation] method = '" + options.method + "' is not available");
}

mrpt::poses::CPose2D COdometryPoseEstimator::update(const TOdometryIncrement& increment,
													const mrpt::obs::CObservation2DRangeScan& /*scan*/)
{
	if (increment.known) m_pose = m_pose + increment.delta;
	return m_pose;
}

}  // namespace hslam::slam
