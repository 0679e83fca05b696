/* hslam: how well a scan fits an ICP reference at a pose, measured sharply
 * enough to choose between the results of several ICP seeds.
 *
 * ICP's goodness (the fraction of points paired within the final, range-
 * growing threshold) cannot tell two basins apart when both pair most of
 * the points: on aces at t = 508.8 s, after a 33 deg turn, the result seeded
 * by a wrong line pairing (14 deg off) and the one seeded by odometry
 * (right) both paired 0.833 of the points. The mean Gaussian likelihood of
 * the points' distances to their nearest reference points (sigma 5 cm, the
 * laser's noise plus the map's blur) gave 0.490 against 0.672. It is the
 * score of the likelihood-field matchers (Thrun et al., Probabilistic
 * Robotics 6.4; Olson 2009), evaluated through the k-d tree ICP already
 * built.
 *
 * With max_segment_m > 0 a point's distance is to the nearest reference
 * segment instead: from its nearest reference point to one of the next two
 * nearest, if they are at most max_segment_m apart (neighbouring samples of
 * one wall). The distance to the nearest point aliases on sampled walls: a
 * scan taken from the reference scan's own pose samples every wall at the
 * same bearings, so at zero motion each point lands on a reference point
 * and fits perfectly, while at the true pose a few decimetres along a
 * corridor the points fall between the samples (1 deg beams hit a wall 1 m
 * to the side every 0.16 m at 3 m ahead, every 0.44 m at 5 m). Laser-only
 * sample started mid-corridor at entry 2200: the scan at t = 147.4 s fitted
 * the zero motion odometry claimed by 0.880 and the true 0.48 m by 0.788
 * with nearest points; with segments the true pose fits as well as zero
 * motion along the walls and better at the corridor's end. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

namespace hslam::matching
{
/** Mean over the points of `current` (robot frame) placed at `pose` of
 * exp(-d^2 / 2 sigma^2), d the distance to the nearest reference point (or
 * segment, max_segment_m > 0: file comment); in [0, 1], 0 without points. */
double alignmentFit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m, double maxSegment_m = 0.0);
/** The same with the reference in a CPointIndex2D (CPointToPointIcp). */
double alignmentFit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m, double maxSegment_m = 0.0);

}  // namespace hslam::matching
