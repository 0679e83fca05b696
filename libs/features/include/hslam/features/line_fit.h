/* hslam: total-least-squares line fit (thesis 4.4.2 ii, eq. 57-64), done in
 * normal form.
 *
 * The thesis minimises the orthogonal error e^2 = (y - m x - c)^2 / (1 + m^2)
 * (eq. 59) and solves K2 m^2 + K1 m - K2 = 0 with K2 = sum dx dy and
 * K1 = sum (dx^2 - dy^2) (eq. 62-64; the printed "+ K2" is a sign typo, the
 * derivative of eq. 59 gives "- K2"). That quadratic is the eigen-problem of
 * the 2x2 scatter matrix S = sum [dx dx, dx dy; dx dy, dy dy] about the
 * centroid written for a slope: its roots are the slopes of the two
 * eigenvectors. Here the line is taken directly as the centroid plus the
 * eigenvector of the largest eigenvalue (direction 0.5 atan2(2 Sxy, Sxx - Syy)),
 * the normal being the other one; no slope appears, so vertical lines are as
 * exact as horizontal ones and the fit is exact on noiseless collinear points. */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <vector>

namespace hslam::features
{
struct TLineFit
{
	bool valid = false;  //!< false for < 2 points or all points identical
	double rho_m = 0;  //!< x cos(alpha) + y sin(alpha) = rho, rho >= 0
	double alpha_rad = 0;  //!< normal direction, (-pi, pi]
	mrpt::math::TPoint2D centroid;
	double rms_m = 0;  //!< RMS orthogonal residual
	double max_residual_m = 0;  //!< largest |orthogonal residual|

	/** Signed orthogonal distance of p to the line (m). */
	double distanceTo(const mrpt::math::TPoint2D& p) const;
	/** Orthogonal projection of p onto the line. */
	mrpt::math::TPoint2D project(const mrpt::math::TPoint2D& p) const;
};

/** TLS fit of all points. */
TLineFit fitLineTotalLeastSquares(const std::vector<mrpt::math::TPoint2D>& points);

/** Normal form (rho >= 0, alpha in (-pi, pi]) of the line through `point`
 * with unit normal (cos(normal_rad), sin(normal_rad)). */
void normalFormThrough(const mrpt::math::TPoint2D& point, double normal_rad, double& rho_m, double& alpha_rad);

/** Angle between two undirected lines given by their normal angles, in [0, pi/2]. */
double lineAngleDifference_rad(double alpha1_rad, double alpha2_rad);

}  // namespace hslam::features
