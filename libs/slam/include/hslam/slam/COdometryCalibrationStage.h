/* hslam: the pipeline's odometry calibration: corrects each scan's odometry
 * increment before the pose estimator sees it, and feeds the estimator's
 * results back as intervals between accepted good matches, to
 *  - calib::COdometryScaleCheck (INI [odometry_scale_check]): odometry that
 *    reports a gross fraction or multiple of the motion is rescaled; an
 *    interval counts if the odometry was known throughout, whatever the
 *    estimator's motion prior (a stall is what such readings cause);
 *  - calib::COdometrySelfCalibration (INI [odometry_self_calibration]), on
 *    the rescaled increments: an interval counts only if the motion prior
 *    was odometry throughout (no gap, no frozen, stalled or jumping
 *    odometry: CMotionPrior). */
#pragma once

#include <hslam/calib/COdometryScaleCheck.h>
#include <hslam/calib/COdometrySelfCalibration.h>
#include <hslam/slam/COdometryTracker.h>
#include <hslam/slam/CPoseEstimator.h>

#include <optional>

namespace hslam::slam
{
class COdometryCalibrationStage
{
   public:
	COdometryCalibrationStage(const calib::TOdometryScaleCheck& scaleCheck, const calib::TOdometrySelfCalibration& options,
							  double nominalWheelbase_m)
		: m_scaleCheck(scaleCheck), m_calibration(options, nominalWheelbase_m)
	{
	}

	const calib::COdometryScaleCheck& scaleCheck() const { return m_scaleCheck; }
	const calib::COdometrySelfCalibration& calibration() const { return m_calibration; }

	/** The increment the estimator is given: corrected by the current fit. */
	TOdometryIncrement correct(const TOdometryIncrement& increment) const;

	/** After the estimator: `uncorrected` is this scan's increment as the
	 * odometry reported it, `estimate` what the estimator made of the scan. */
	void observe(const TOdometryIncrement& uncorrected, const TPoseEstimate& estimate);

   private:
	calib::COdometryScaleCheck m_scaleCheck;
	calib::COdometrySelfCalibration m_calibration;
	mrpt::poses::CPose2D m_reportedSinceMatch;  //!< as reported, since the last accepted match
	bool m_knownSinceMatch = false;  //!< odometry known throughout since that match
	mrpt::poses::CPose2D m_odometrySinceMatch;  //!< rescaled (scale check), since the last accepted match
	std::optional<mrpt::poses::CPose2D> m_poseAtMatch;  //!< fused pose at that match
	bool m_clean = false;  //!< odometry known and trusted since that match
};

}  // namespace hslam::slam
