/* hslam: laser-only odometry for logs without wheel odometry (e.g. the
 * legs data: no odometry, no tf): each scan is aligned by MRPT's CICP
 * against the world points of recent keyframes (CKeyframePointMap, as
 * MRPT's icp-slam does), seeded by the previous motion. Matching only the
 * previous scan drifts like a random walk. Poses of the sensor frame, the
 * first at the origin. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::matching
{
std::vector<mrpt::poses::CPose2D> icpOdometry(const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans);
}  // namespace hslam::matching
