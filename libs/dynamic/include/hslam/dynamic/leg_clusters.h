/* hslam: the clusters a learned leg classifier looks at (beyond the thesis:
 * its 4.7.1 rules accept or reject segments cut at 300 mm; 4.7.5 / 5.2 ask
 * for better leg recognition). Segmentation as in leg_tracker (Leigh et al.,
 * ICRA 2015) and Arras et al. (ICRA 2007): valid beams nearer than a range
 * limit are flood-filled into one cluster when their end points are closer
 * than cluster_distance_m, searching forward only as many beams as that
 * distance subtends at the beam's range, so a cluster may skip an invalid
 * beam or a mixed pixel but never grows along a whole wall seen edge-on
 * by accident. Clusters with fewer than min_points are dropped. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace hslam::dynamic
{
/** One cluster: beam indices in increasing order and their end points in
 * the robot frame (the scan's sensorPose applied). */
struct TScanCluster
{
	std::vector<size_t> beams;
	std::vector<mrpt::math::TPoint2D> points;
	mrpt::math::TPoint2D centroid;  //!< mean of points (robot frame)
	size_t firstBeam() const { return beams.front(); }
	size_t lastBeam() const { return beams.back(); }
};

struct TClusterOptions
{
	double cluster_distance_m = 0.13;  //!< leg_tracker: 0.13 m
	int min_points = 3;  //!< leg_tracker: 3
	double max_range_m = 5.0;  //!< beams farther than this are ignored (m)
};

/** Clusters of `scan` in beam order (see file comment). NaN, inf, zero and
 * flagged-invalid ranges never join a cluster. */
std::vector<TScanCluster> clusterScan(const mrpt::obs::CObservation2DRangeScan& scan, const TClusterOptions& options);

}  // namespace hslam::dynamic
