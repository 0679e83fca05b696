/* hslam: images of the pose estimate, no file I/O:
 *  - renderPosePlot: x, y (m) and theta (deg) over time, estimate with its
 *    +-1 sigma band and dead reckoning (like thesis figures 117-127);
 *  - renderScanDebugImage: one scan in the robot frame with its extracted
 *    line segments and their endpoints (like thesis figures 88 and 95). */
#pragma once

#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/img/CImage.h>

namespace hslam::slam
{
mrpt::img::CImage renderPosePlot(const std::vector<CMappingPipeline::TTimedEstimate>& estimates,
								 const common::TTrajectory2D& odometry, int widthPx = 1200, int panelHeightPx = 260);

mrpt::img::CImage renderScanDebugImage(const mrpt::obs::CObservation2DRangeScan& scan, const TPoseEstimate& estimate,
									   double halfWidth_m = 8.0, int sizePx = 640);

}  // namespace hslam::slam
