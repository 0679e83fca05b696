/* hslam graph (private): a submap to test against the current keyframe, and
 * what is kept of a submap while it is being matched. */
#pragma once

#include <hslam/graph/CLoopClosureDetector.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <optional>

namespace hslam::graph
{
struct CLoopClosureDetector::TCandidate
{
	size_t submap = 0;
	double distance_m = 0;  //!< current pose to the submap's anchor
	Eigen::Matrix3d relativeCovariance = Eigen::Matrix3d::Identity();  //!< current vs anchor, world frame
	double xy_std_m = 0, yaw_std_rad = 0;  //!< of relativeCovariance: largest xy axis, heading
	TSearchWindow window;
	double information_gain_nats = 0;  //!< closureInformationGain of relativeCovariance
	std::optional<TClosureTrack> track;  //!< verified from this closure, not searched
};

/** A submap's likelihood field, its points as an MRPT map for the ICP check
 * and its observed free space: built once when the submap is first matched (the points map
 * keeps its k-d tree between ICP calls). */
struct CLoopClosureDetector::TSubmapField
{
	CCorrelativeScanMatcher matcher;
	mrpt::maps::CSimplePointsMap points;
	CObservedFreeSpace free;  //!< cells the submap's beams crossed, on the matcher's grid
};
}  // namespace hslam::graph
