/* hslam: raw odometry increments between front scans of a CARMEN log.
 *
 * Verified on intel/aces/csail-corrected: the FLASER x,y,theta (and odom_*)
 * fields hold the corrected REFERENCE pose; right after each FLASER an
 * "ODOM ... 0" line equal to that pose RE-ANCHORS odometry there, and the
 * following ODOM lines are raw odometry continuing from it (e.g. intel line
 * 176: anchor (0.600266,-0.0320327,-0.354665), next ODOM (0.600266,
 * -0.0320327,-0.41612)). ODOM timestamps often go backwards (intel line 174
 * is older than line 173), so odometry is paired with scans by FILE ORDER.
 *
 * Rule (also right for uncorrected logs without anchors): an ODOM is an
 * anchor if it is the first ODOM after a laser with a pose and equals one of
 * that laser's poses within kAnchorTolerance; the anchor becomes the base of
 * the next increment. Any other ODOM is fresh raw odometry. At each front scan
 * the increment since the previous front scan is base^-1 (+) lastOdom if fresh
 * odometry arrived, and MISSING otherwise (never zero motion: some logs lack
 * odometry between scans, one almost entirely). A rear laser followed by an
 * anchor splits the interval in two segments, which are composed.
 *
 * Our own absolute chain: chain_0 = the last raw ODOM before the first front
 * scan (identity if none), chain_{k+1} = chain_k (+) increment_k, identity
 * when the increment is missing. */
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <vector>

namespace hslam::io
{
/** Max |difference| of x, y (m) and theta (rad) for an ODOM to be an anchor. */
constexpr double kAnchorTolerance = 1e-6;

struct TCarmenOdometryStep
{
	bool first = false;  //!< first front scan: no increment needed
	bool incrementKnown = false;
	mrpt::poses::CPose2D increment;  //!< from the previous front scan (if known)
	mrpt::poses::CPose2D chainPose;  //!< our absolute odometry at this scan
	bool hasVelocities = false;  //!< an ODOM was seen; tv/rv are its velocities
	double tv_mps = 0, rv_radps = 0;
};

class CCarmenOdometryTracker
{
   public:
	/** Feeds one ODOM line; returns true if it was taken as an anchor. */
	bool addOdometry(const mrpt::math::TPose2D& pose, double tv_mps, double rv_radps);

	/** A front scan with its poses (reference first); returns its odometry step. */
	TCarmenOdometryStep addFrontScan(const std::vector<mrpt::math::TPose2D>& scanPoses);

	/** A rear scan with poses: only an anchor after it matters. */
	void addRearScan(const std::vector<mrpt::math::TPose2D>& scanPoses);

	size_t anchors() const { return m_anchors; }

   private:
	/** Appends base^-1 (+) lastOdom to the accumulated increment (or marks it missing). */
	void closeSegment();
	bool isAnchor(const mrpt::math::TPose2D& pose) const;

	std::optional<mrpt::poses::CPose2D> m_base;  //!< odometry at the start of the current segment
	std::optional<mrpt::poses::CPose2D> m_lastOdom;
	bool m_fresh = false;  //!< raw odometry arrived since m_base was set
	mrpt::poses::CPose2D m_accumulated;  //!< increment since the previous front scan
	bool m_accumulatedKnown = true;
	std::vector<mrpt::math::TPose2D> m_awaitingAnchor;  //!< poses of the last laser, until the next ODOM
	bool m_awaitingAfterRear = false;
	bool m_seenFrontScan = false;
	mrpt::poses::CPose2D m_chain;
	double m_tv_mps = 0, m_rv_radps = 0;
	size_t m_anchors = 0;
};

}  // namespace hslam::io
