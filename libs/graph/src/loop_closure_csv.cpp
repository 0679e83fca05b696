#include <hslam/graph/CLoopClosureDetector.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace hslam::graph
{
std::string loopClosureCsvHeader()
{
	return "query_keyframe,anchor_keyframe,submap,accepted,reason,score,hit_fraction,second_score,icp_goodness,"
		   "icp_shift_m,icp_shift_deg,consistency_chi2,window_xy_m,window_yaw_deg,rel_x_m,rel_y_m,rel_yaw_deg,"
		   "query_x_m,query_y_m,matched_x_m,matched_y_m,anchor_x_m,anchor_y_m,match_ms,free_side_fraction,"
		   "prior_xy_std_m,prior_yaw_std_deg,information_gain_nats,tracked_in_a_row,match_xy_std_m,match_yaw_std_deg";
}

std::string loopClosureCsvRow(const TLoopClosure& c)
{
	std::ostringstream o;
	o.precision(6);
	o << c.query_keyframe_id << ',' << c.anchor_keyframe_id << ',' << c.submap << ',' << (c.accepted ? 1 : 0) << ','
	  << c.reason << ',' << c.score << ',' << c.hit_fraction << ',' << c.second_score << ',' << c.icp_goodness << ','
	  << c.icp_shift_m << ',' << mrpt::RAD2DEG(c.icp_shift_yaw_rad) << ',' << c.consistency_chi2 << ','
	  << c.window_xy_m << ',' << mrpt::RAD2DEG(c.window_yaw_rad) << ',' << c.relative.x << ',' << c.relative.y << ','
	  << mrpt::RAD2DEG(c.relative.phi) << ',' << c.query_pose_estimate.x << ',' << c.query_pose_estimate.y << ','
	  << c.query_pose_matched.x << ',' << c.query_pose_matched.y << ',' << c.anchor_pose.x << ',' << c.anchor_pose.y
	  << ',' << c.match_ms << ',' << c.free_side_fraction << ',' << c.prior_xy_std_m << ','
	  << mrpt::RAD2DEG(c.prior_yaw_std_rad) << ',' << c.information_gain_nats << ',' << c.tracked_in_a_row << ',';
	if (c.has_covariance)  // else both empty
		o << std::sqrt(largestXyVariance(c.covariance)) << ',' << mrpt::RAD2DEG(std::sqrt(std::max(0.0, c.covariance(2, 2))));
	else
		o << ',';
	return o.str();
}
}  // namespace hslam::graph
