/* hslam graph: relative pose uncertainty between keyframes of a pose graph
 * with loops, by Olson's "Dijkstra projection" (E. Olson, "Recognizing places
 * using spectrally clustered local matches", RAS 2009, sec. 3; also used for
 * loop-closure gating in his thesis, MIT 2008, ch. 4).
 *
 * The loop-closure search needs, for every candidate submap, the covariance
 * of the current keyframe relative to the submap's anchor: it sizes the
 * search window and gates the closure's implied correction. The difference
 * of two marginal chain covariances (Sigma_q - J Sigma_a J^T) is that
 * covariance only while both nodes lie on one chain from the origin; after a
 * loop closure tightens the current node, an anchor in a drifted stretch
 * has the larger marginal, the difference is negative, its floor made the
 * window minimal and the gate rejected accurate closures as "inconsistent"
 * (intel: 288 of 382 such rejections were within 0.1 m / 1 deg of the
 * reference). The projection instead propagates the covariance from the
 * current node outwards along the path of least accumulated uncertainty
 * through all active edges, sequential and loop: a conservative (never
 * overconfident along that path) estimate of the relative uncertainty. */
#pragma once

#include <hslam/graph/CPoseGraph.h>

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace hslam::graph
{
/** Covariance (world frame, first order) of every node's pose with `source`
 * held fixed, propagated through the active edges of `graph` along the path
 * that minimises the trace of the accumulated covariance (Dijkstra, greedy as
 * in Olson 2009). Unreachable nodes have no value; the source has zero. */
std::vector<std::optional<Eigen::Matrix3d>> dijkstraProjection(const CPoseGraph& graph, size_t source);

/** Converts the covariance of `node` with `source` fixed (world frame) into
 * the covariance of `source` with `node` fixed (world frame), through the
 * inverse of their relative pose (first order). */
Eigen::Matrix3d swapFixedEnd(const mrpt::math::TPose2D& source, const mrpt::math::TPose2D& node,
							 const Eigen::Matrix3d& nodeGivenSource);

}  // namespace hslam::graph
