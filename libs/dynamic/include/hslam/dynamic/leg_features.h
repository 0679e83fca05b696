/* hslam: geometric features of one scan cluster for the learned leg
 * classifier (CLegClassifier). The set of Arras, Mozos and Burgard, "Using
 * boosted features for the detection of people in 2D range data" (ICRA
 * 2007), as leg_tracker (Leigh et al., ICRA 2015) computes it, plus the
 * distance from the sensor and the two edge gaps:
 *   points                number of points
 *   std_dev_m             standard deviation of the points from their centroid
 *   median_deviation_m    mean distance of the points from their median
 *   width_m               first to last point
 *   linearity_m2          sum of squared residuals of a total-least-squares line
 *   circularity_m2        sum of squared residuals of an algebraic circle fit
 *   radius_m              radius of that circle (clamped to 10 m)
 *   boundary_length_m     polyline length through the points
 *   boundary_regularity_m standard deviation of the polyline steps
 *   mean_curvature_1pm    mean curvature of consecutive point triples
 *   mean_angle_diff_rad   mean turning angle between consecutive steps
 *   range_m               distance of the centroid from the sensor
 *   gap_before_m          range behind the first beam's neighbour minus the
 *   gap_after_m           first beam's range (likewise after the last beam):
 *                         > 0 the cluster stands in front, no return = +2 m,
 *                         clamped to [-2, 2] m (Arras' jump distances)
 *   missing_beams         beams inside the cluster's span that did not join
 *                         it (no return, or a mixed pixel)
 *   neighbour_m           distance to the nearest other cluster's centroid,
 *                         clamped to 3 m (a person has two legs)
 *   neighbour_width_m     width of that cluster (0 if none within 3 m)
 *   neighbours_1m         other clusters with a centroid within 1 m (a
 *                         chair or table has three or four legs)
 * All lengths in metres, in the robot frame. */
#pragma once

#include <hslam/dynamic/leg_clusters.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <array>

namespace hslam::dynamic
{
constexpr size_t kLegFeatureCount = 18;
using TLegFeatures = std::array<float, kLegFeatureCount>;

/** Name of feature k (CSV headers, importance tables). */
const char* legFeatureName(size_t k);

/** Features of clusters[k], one of the clusters of `scan` (see file comment). */
TLegFeatures legFeatures(const std::vector<TScanCluster>& clusters, size_t k,
						 const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace hslam::dynamic
