/* hslam: the pipeline's odometry self-calibration (calib::COdometrySelfCalibration,
 * INI [odometry_self_calibration]): corrects each scan's odometry increment
 * before the pose estimator sees it, and feeds the estimator's results back
 * as intervals between accepted matches.
 *
 * An interval is used only if the odometry was known and the estimator's
 * motion prior was odometry throughout (no gap, no frozen or jumping
 * odometry: CMotionPrior), and it ends at a good match the UKF accepted. */
#pragma once

#include <hslam/calib/COdometrySelfCalibration.h>
#include <hslam/slam/COdometryTracker.h>
#include <hslam/slam/CPoseEstimator.h>

#include <optional>

namespace hslam::slam
{
class COdometryCalibrationStage
{
   public:
	COdometryCalibrationStage(const calib::TOdometrySelfCalibration& options, double nominalWheelbase_m)
		: m_calibration(options, nominalWheelbase_m)
	{
	}

	const calib::COdometrySelfCalibration& calibration() const { return m_calibration; }

	/** The increment the estimator is given: corrected by the current fit. */
	TOdometryIncrement correct(const TOdometryIncrement& increment) const;

	/** After the estimator: `uncorrected` is this scan's increment as the
	 * odometry reported it, `estimate` what the estimator made of the scan. */
	void observe(const TOdometryIncrement& uncorrected, const TPoseEstimate& estimate);

   private:
	calib::COdometrySelfCalibration m_calibration;
	mrpt::poses::CPose2D m_odometrySinceMatch;  //!< uncorrected, since the last accepted match
	std::optional<mrpt::poses::CPose2D> m_poseAtMatch;  //!< fused pose at that match
	bool m_clean = false;  //!< odometry known and trusted since that match
};

}  // namespace hslam::slam
