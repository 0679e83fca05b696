/* hslam: covariance of a converged 2D scan alignment from the geometry of the
 * matched surfaces (point-to-line information matrix, the approach of Censi's
 * closed-form ICP covariance, simplified to its dominant term).
 *
 * Each point p of the aligned scan, lying on a reference surface with normal
 * n (from the k nearest reference points), constrains the pose only along n:
 *     J = [n_x, n_y, n . d(R p)/dtheta],   H = sum J' J,
 *     cov = sigma^2 * correlation_factor * H^-1,
 * sigma^2 the point-to-line residual variance. In a corridor every normal is
 * perpendicular to the axis, H is singular along it and the variance there
 * becomes huge, so the UKF keeps the odometry for that direction: MRPT's ICP
 * covariance (finite differences of the matching error) is small in every
 * direction there, and the estimate slid along simulated corridors. */
#pragma once

#include <hslam/matching/CPointIndex2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

#include <vector>

namespace hslam::matching
{
struct TGeometricCovarianceOptions
{
	int normal_neighbours = 6;  //!< reference points used to fit each normal
	double max_match_distance_m = 0.2;  //!< points further from the reference surface are outliers
	double min_sigma_m = 0.02;  //!< floor of the residual std (laser noise)
	double correlation_factor = 10.0;  //!< points per independent error (neighbouring beams are correlated)
	/** A current point counts min(1, d / this) of a point, d its distance to
	 * the previous point in scan order: information per length of wall, not
	 * per beam. A near wall is sampled every few millimetres and those beams'
	 * errors are one error; a far wall every few centimetres. 0 = every
	 * point counts fully. */
	double full_weight_spacing_m = 0.0;
	double max_std_m = 100.0;  //!< cap of the std in an unconstrained direction
	/** A translation direction along which fewer than this fraction of the
	 * matched points constrain the pose (eigenvalue of the unit-weight
	 * information of the translation) counts as unconstrained: its variance
	 * gets the cap. A few points (a door recess in a corridor) do not outweigh the pull
	 * of a hundred wall points on a point-to-point ICP, whose result along the
	 * corridor is then biased towards the seed (issue 12, "long featureless
	 * corridor"); 0 = off. */
	double degenerate_min_fraction = 0.0;
};

/** Covariance of `pose` (pose of the current scan in the reference frame);
 * nullopt-like identity*max_std^2 if fewer than 10 points match. */
Eigen::Matrix3d geometricAlignmentCovariance(const mrpt::maps::CSimplePointsMap& reference,
											 const mrpt::maps::CSimplePointsMap& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& options, size_t* matchedPoints = nullptr);
/** The same for current points given in the robot frame. */
Eigen::Matrix3d geometricAlignmentCovariance(const mrpt::maps::CSimplePointsMap& reference,
											 const std::vector<mrpt::math::TPoint2D>& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& options, size_t* matchedPoints = nullptr);

/** The same with the reference in a CPointIndex2D (CPointToPointIcp). */
Eigen::Matrix3d geometricAlignmentCovariance(const CPointIndex2D& reference,
											 const mrpt::maps::CSimplePointsMap& current,
											 const mrpt::poses::CPose2D& pose,
											 const TGeometricCovarianceOptions& options, size_t* matchedPoints = nullptr);

/** `pose` moved by up to `steps` damped Gauss-Newton steps on the same
 * point-to-line residuals (each point along its reference normal).
 * Point-to-point ICP on walls sampled every few centimetres has fixed points
 * short of the truth: a scan pairs with its neighbours along the wall, and
 * that pull holds the pose (a noise-free room: 1.1 deg off from a 2 deg
 * seed, 2.3 deg from 10-90 deg, with either ICP engine). Along a normal
 * there is no such pull. */
mrpt::poses::CPose2D refinedAlongNormals(const CPointIndex2D& reference, const mrpt::maps::CSimplePointsMap& current,
										 mrpt::poses::CPose2D pose, const TGeometricCovarianceOptions& options,
										 int steps);

}  // namespace hslam::matching
