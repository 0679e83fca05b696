/* hslam: MRPT observations built from CARMEN messages (sensor labels,
 * timestamps, scan geometry and validity). */
#pragma once

#include <hslam/io/CCarmenOdometryTracker.h>
#include <hslam/io/carmen_messages.h>
#include <hslam/io/carmen_range_limits.h>
#include <hslam/io/carmen_scan_geometry.h>

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationOdometry.h>

#include <string>

namespace hslam::io
{
/** Range noise sigma of the SICK LMS200 (CARMEN's reader also assumes 0.01 m). */
constexpr float kCarmenRangeStdError_m = 0.01f;

/** "LASER" (FLASER, ROBOTLASER1, RAWLASER1), "REAR_LASER" (RLASER,
 * ROBOTLASER2), "LASER2".."LASER4" (RAWLASER2..4). */
std::string carmenScanLabel(const TCarmenLaser& laser);

/** The scan as MRPT sees it: ranges, validity from `limits`, aperture,
 * rightToLeft = true, sensorPose, maxRange, stdError. */
mrpt::obs::CObservation2DRangeScan::Ptr makeCarmenScan(const TCarmenLaser& laser, const TCarmenScanGeometry& geometry,
													   const mrpt::poses::CPose3D& sensorPose,
													   const TCarmenRangeLimits& limits, double t_s);

/** Absolute odometry (our chain) at a scan, label "ODOMETRY". */
mrpt::obs::CObservationOdometry::Ptr makeCarmenOdometry(const TCarmenOdometryStep& step, double t_s);

mrpt::obs::CObservationComment::Ptr makeComment(const std::string& label, const std::string& text, double t_s);

}  // namespace hslam::io
