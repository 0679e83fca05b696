#include <hslam/slam/CPoseEstimator.h>
#include <hslam/slam/CLocalMapPoseEstimator.h>
#include <hslam/slam/CScanMatchingPoseEstimator.h>

#include <stdexcept>

namespace hslam::slam
{
std::unique_ptr<CPoseEstimator> createPoseEstimator(const TPoseEstimationOptions& options,
													const mrpt::config::CConfigFileBase& cfg,
													common::CStageTimer& timer)
{
	if (options.method == "odometry") return std::make_unique<COdometryPoseEstimator>();
	if (options.method == "lines" || options.method == "icp" || options.method == "lines+icp")
		return std::make_unique<CScanMatchingPoseEstimator>(options, cfg, timer);
	if (options.method == "map" || options.method == "lines+map")
		return std::make_unique<CLocalMapPoseEstimator>(options, cfg, timer);
	throw std::invalid_argument("[pose_estimation] method = '" + options.method + "' is not available");
}

TPoseEstimate COdometryPoseEstimator::update(const TOdometryIncrement& increment, const common::TRangeData& /*scan*/,
											 const std::vector<bool>* /*excludedBeams*/)
{
	if (increment.known) m_pose = m_pose + increment.delta;
	TPoseEstimate estimate;
	estimate.pose = m_pose;
	return estimate;
}

}  // namespace hslam::slam
