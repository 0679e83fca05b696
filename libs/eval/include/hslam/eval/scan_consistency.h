/* hslam: how well a trajectory explains the laser scans it was estimated
 * from, without any reference trajectory.
 *
 * Each scan is placed at its pose and compared with the scan before it:
 * the misfit of the pair is the mean, over the later scan's points, of the
 * distance to the nearest point of the earlier scan, each distance capped at
 * truncate_m (points that see space the earlier scan did not see, or a
 * person, count as the cap, not as metres of error). A heading slip of a few
 * degrees between two scans shows as a misfit two to three times the usual.
 *
 * It is the check for the reference poses themselves: the CARMEN "corrected"
 * logs are the output of another SLAM system, and where the reference's step
 * misfits the scans clearly more than the estimate's, the reference is what
 * slipped (csail, t = 397 s: the reference turns 48 deg between two scans
 * whose walls agree on 36 deg; misfit 0.183 m against the estimate's
 * 0.085 m). An ATE against such a reference counts its slips as ours.
 * Scan matching fitness in the spirit of Olson, "Real-time correlative scan
 * matching" (ICRA 2009), applied to consecutive scans only, so that drift
 * over a long loop does not enter: this measures local consistency, ATE the
 * global one. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <string>
#include <vector>

namespace hslam::eval
{
struct TScanConsistencyOptions
{
	/** Largest |t_scan - t_pose| for a scan to take a trajectory pose (s). */
	double max_dt_s = 0.02;
	/** Returns farther than this are left out (sparse, their angular error dominates) (m). */
	double max_range_m = 20.0;
	/** A point's distance to the earlier scan counts at most this (m). */
	double truncate_m = 0.3;
	/** A pair misfits "clearly" more under one trajectory than under the
	 * other when the difference is above this (m); about the misfit of a
	 * 2 deg heading error at 2 m. */
	double clearly_m = 0.03;
};

/** One laser scan's valid returns in the robot frame, with its time. */
struct TScanPoints2D
{
	double t_s = 0;
	std::vector<mrpt::math::TPoint2D> points;
};

/** A scan pair (this scan and the one before it) under two trajectories. */
struct TScanPairMisfit
{
	double t_s = 0;  //!< time of the later scan
	double reference_m = 0;  //!< misfit with both scans at reference poses
	double estimate_m = 0;  //!< misfit with both scans at estimate poses
};

struct TScanConsistency
{
	size_t scans = 0;  //!< scans given
	std::vector<TScanPairMisfit> pairs;  //!< consecutive pairs posed by both trajectories
	double reference_mean_m = 0, estimate_mean_m = 0;  //!< mean misfit over `pairs`
	/** Pairs where the estimate misfits more (less) than the reference by
	 * more than clearly_m. */
	std::vector<TScanPairMisfit> estimate_worse, estimate_better;
};

/** The valid returns of every 2D range scan of a rawlog with the label
 * `laserLabel` ("" = the only laser label there is; std::runtime_error,
 * naming the labels, if there are several, and naming the file if there is
 * none). Points farther than max_range_m are left out. */
std::vector<TScanPoints2D> readScanPoints(const std::string& rawlogPath, const std::string& laserLabel,
										  double max_range_m);

/** Misfit of each pair of consecutive scans (both posed by both
 * trajectories within max_dt_s). Throws std::runtime_error when no pair is
 * posed by both. */
TScanConsistency compareScanConsistency(const std::vector<TScanPoints2D>& scans,
										const common::TTrajectory2D& reference, const common::TTrajectory2D& estimate,
										const TScanConsistencyOptions& options);

}  // namespace hslam::eval
