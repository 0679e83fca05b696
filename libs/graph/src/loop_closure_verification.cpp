/* CLoopClosureDetector: verification of one candidate (score, uniqueness,
 * ICP agreement, consistency with the odometry chain). */
#include <hslam/graph/CLoopClosureDetector.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/slam/CICP.h>

#include <Eigen/Dense>
#include <chrono>

#include "loop_closure_candidate.h"

namespace hslam::graph
{
namespace
{
mrpt::maps::CSimplePointsMap toPointsMap(const TPointCloud2D& points)
{
	mrpt::maps::CSimplePointsMap map;
	map.reserve(points.size());
	for (const auto& p : points) map.insertPointFast(p.x, p.y, 0);
	return map;
}

/** Rotates a covariance given in the frame of `frame` into the world frame. */
Eigen::Matrix3d toWorld(const Eigen::Matrix3d& cov, double frameYaw_rad)
{
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	R(0, 0) = std::cos(frameYaw_rad), R(0, 1) = -std::sin(frameYaw_rad);
	R(1, 0) = std::sin(frameYaw_rad), R(1, 1) = std::cos(frameYaw_rad);
	return R * cov * R.transpose();
}

bool reject(TLoopClosure& c, const char* why)
{
	c.accepted = false;
	c.reason = why;
	return false;
}
}  // namespace

bool CLoopClosureDetector::matchBest(const CCorrelativeScanMatcher& m, const TCandidate& c, TLoopClosure& out,
									  TCorrelativeMatch& best) const
{
	const auto guess = relativePose(out.anchor_pose, out.query_pose_estimate);
	best = m.match(m_query, guess, c.window, nullptr, m_options.min_score, EMatchOutput::pose_only);
	out.score = best.score, out.hit_fraction = best.hit_fraction;
	if (!best.found || best.score < m_options.min_score) return reject(out, "low score");
	out.relative = best.pose;
	if (best.hit_fraction < m_options.min_hit_fraction) return reject(out, "low overlap");
	return true;
}

bool CLoopClosureDetector::matchTracked(const CCorrelativeScanMatcher& m, const TCandidate& c, const CPoseGraph& graph,
										TLoopClosure& out, TCorrelativeMatch& best) const
{
	const auto& nodes = graph.nodes();
	const auto guess = composePose(c.track->relative, relativePose(nodes[c.track->node].pose, nodes[out.query_node].pose));
	best = m.matchNear(m_query, guess, m_options.min_score);
	out.tracked_in_a_row = c.track->in_a_row + 1;
	out.score = best.score, out.hit_fraction = best.hit_fraction;
	if (!best.found) return reject(out, "low score");
	out.relative = best.pose;
	if (best.hit_fraction < m_options.min_hit_fraction) return reject(out, "low overlap");
	return true;
}

bool CLoopClosureDetector::checkUniqueness(const CCorrelativeScanMatcher& m, const TCandidate& c,
										   const TCorrelativeMatch& best, TLoopClosure& out) const
{
	const auto guess = relativePose(out.anchor_pose, out.query_pose_estimate);
	// whether a second peak exists is all the test needs: the search stops at the first
	const bool thinned = m_options.ambiguity_thinned;
	const TSearchExclusion near{best.pose, m_options.ambiguity_xy_m, m_options.ambiguity_yaw_rad, true, thinned};
	const TSearchWindow wider{c.window.xy_m * m_options.ambiguity_window_factor, c.window.yaw_rad};
	const double scale = thinned ? best.search_score : best.score;
	const auto second =
		m.match(m_query, guess, wider, &near, m_options.ambiguity_ratio * scale, EMatchOutput::pose_only);
	if (!second.found) return true;
	out.second_score = second.score;
	return reject(out, "ambiguous");
}

bool CLoopClosureDetector::checkConsistency(const TCandidate& c, TLoopClosure& out) const
{
	// the correction the closure implies for the current pose, against the chain's uncertainty
	const auto matched = composePose(out.anchor_pose, out.relative);
	const Eigen::Vector3d d(matched.x - out.query_pose_estimate.x, matched.y - out.query_pose_estimate.y,
							mrpt::math::wrapToPi(matched.phi - out.query_pose_estimate.phi));
	const Eigen::Matrix3d S = c.relativeCovariance + toWorld(out.covariance, out.anchor_pose.phi);
	out.consistency_chi2 = d.dot(S.ldlt().solve(d));
	if (out.consistency_chi2 > m_options.consistency_chi2) return reject(out, "inconsistent with the graph");
	return true;
}

bool CLoopClosureDetector::checkFreeSide(const TSubmapField& field, TLoopClosure& out) const
{
	out.free_side_fraction = freeSideFigures(field.matcher.grid(), field.free, m_queryPoints, out.relative).fraction();
	if (out.free_side_fraction < m_options.min_free_side_fraction) return reject(out, "walls seen from behind");
	return true;
}

bool CLoopClosureDetector::refineWithIcp(const TSubmapField& field, TLoopClosure& out) const
{
	const auto current = toPointsMap(m_queryPoints);
	mrpt::slam::CICP icp;
	icp.options.maxIterations = 50;
	icp.options.thresholdDist = 0.3;
	icp.options.thresholdAng = mrpt::DEG2RAD(2.0);
	icp.options.smallestThresholdDist = 0.02;
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.Align(&field.points, &current, mrpt::poses::CPose2D(out.relative), info);
	mrpt::poses::CPosePDFGaussian g;
	g.copyFrom(*pdf);
	out.icp_goodness = info.goodness;
	const auto shift = relativePose(out.relative, g.mean.asTPose());
	out.icp_shift_m = std::hypot(shift.x, shift.y);
	out.icp_shift_yaw_rad = std::abs(mrpt::math::wrapToPi(shift.phi));
	if (info.goodness < m_options.min_icp_goodness) return reject(out, "icp failed");
	if (out.icp_shift_m > m_options.icp_max_shift_m || out.icp_shift_yaw_rad > m_options.icp_max_shift_yaw_rad)
		return reject(out, "icp disagrees");
	out.relative = g.mean.asTPose();
	return true;
}

TLoopClosure CLoopClosureDetector::verify(const TCandidate& c, const TSubmapField& field, size_t node,
										  const CPoseGraph& graph) const
{
	const auto t0 = std::chrono::steady_clock::now();
	const auto& sm = m_submaps[c.submap];
	TLoopClosure out;
	out.query_node = node, out.anchor_node = sm.anchor_node, out.submap = c.submap;
	out.query_keyframe_id = graph.nodes()[node].keyframe_id;
	out.anchor_keyframe_id = graph.nodes()[sm.anchor_node].keyframe_id;
	out.query_pose_estimate = graph.nodes()[node].pose;
	out.anchor_pose = graph.nodes()[sm.anchor_node].pose;
	out.window_xy_m = c.window.xy_m, out.window_yaw_rad = c.window.yaw_rad;
	out.prior_xy_std_m = c.xy_std_m, out.prior_yaw_std_rad = c.yaw_std_rad;
	out.information_gain_nats = c.information_gain_nats;
	auto finish = [&]() {
		out.query_pose_matched = composePose(out.anchor_pose, out.relative);
		out.match_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
		return out;
	};
	out.relative = relativePose(out.anchor_pose, out.query_pose_estimate);
	if (static_cast<int>(m_queryPoints.size()) < m_options.min_query_points)
		return reject(out, "too few points"), finish();
	// a closure must pass all tests, so their order changes only the cost
	// and which reason a rejected one records: score, ICP, free side,
	// uniqueness (a second search), then the consistency gate, the only one
	// that needs the closure's score-surface covariance
	TCorrelativeMatch best;
	const bool matched = c.track ? matchTracked(field.matcher, c, graph, out, best) : matchBest(field.matcher, c, out, best);
	if (!matched || !refineWithIcp(field, out) || !checkFreeSide(field, out)) return finish();
	if (!c.track && !checkUniqueness(field.matcher, c, best, out)) return finish();
	// the score-surface covariance only for a closure that passed every test
	// that does not need it (intel: 259 ambiguous candidates no longer pay it)
	out.covariance = field.matcher.covarianceOf(m_query, best);
	out.has_covariance = true;
	if (!checkConsistency(c, out)) return finish();
	out.accepted = true;
	out.reason = "accepted";
	return finish();
}

}  // namespace hslam::graph
