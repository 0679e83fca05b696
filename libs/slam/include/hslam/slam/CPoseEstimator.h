/* hslam: the pose-estimation seam of the pipeline (thesis figure 55: odometry
 * and scan matching fused in a UKF). `[pose_estimation] method` selects the
 * implementation; this foundation has "odometry" (dead reckoning, as thesis
 * 4.6.4 before the UKF was switched on). */
#pragma once

#include <hslam/slam/COdometryTracker.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <memory>
#include <string>

namespace hslam::slam
{
class CPoseEstimator
{
   public:
	virtual ~CPoseEstimator() = default;
	virtual std::string name() const = 0;
	/** Robot pose (world frame) at the time of `scan`, given the odometry
	 * increment since the previous scan. */
	virtual mrpt::poses::CPose2D update(const TOdometryIncrement& increment,
										const mrpt::obs::CObservation2DRangeScan& scan) = 0;
};

struct TPoseEstimationOptions
{
	std::string method = "odometry";  //!< pose source: "odometry"

	template <class V>
	void visit(V& v)
	{
		v.choice("method", method, {"odometry"});
	}
};

/** Builds the estimator named by options.method; `cfg` gives it access to
 * its own INI sections. */
std::unique_ptr<CPoseEstimator> createPoseEstimator(const TPoseEstimationOptions& options,
													const mrpt::config::CConfigFileBase& cfg);

/** Dead reckoning: composes odometry increments from the start pose (0,0,0).
 * Unknown increments leave the pose unchanged (nothing better is known). */
class COdometryPoseEstimator : public CPoseEstimator
{
   public:
	std::string name() const override { return "odometry"; }
	mrpt::poses::CPose2D update(const TOdometryIncrement& increment,
								const mrpt::obs::CObservation2DRangeScan& scan) override;

   private:
	mrpt::poses::CPose2D m_pose;
};

}  // namespace hslam::slam
