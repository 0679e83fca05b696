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
 * built. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

namespace hslam::matching
{
/** Mean over the points of `current` (robot frame) placed at `pose` of
 * exp(-d^2 / 2 sigma^2), d the distance to the nearest reference point; in
 * [0, 1], 0 without points. */
double alignmentFit(const mrpt::maps::CSimplePointsMap& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m);
/** The same with the reference in a CPointIndex2D (CPointToPointIcp). */
double alignmentFit(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
					const mrpt::poses::CPose2D& pose, double sigma_m);

}  // namespace hslam::matching
