/* hslam graph (private): a submap to test against the current keyframe. */
#pragma once

#include <hslam/graph/CLoopClosureDetector.h>

namespace hslam::graph
{
struct CLoopClosureDetector::TCandidate
{
	size_t submap = 0;
	double distance_m = 0;  //!< current pose to the submap's anchor
	Eigen::Matrix3d relativeCovariance = Eigen::Matrix3d::Identity();  //!< current vs anchor, world frame
	TSearchWindow window;
};
}  // namespace hslam::graph
