/* hslam: how well a scan's own surfaces constrain a translation, from normals
 * fitted along the scan (not to a matcher's reference). */
#pragma once

#include <Eigen/Core>
#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace hslam::matching
{
/** The translation information of a scan, normalised: each point counts
 * min(1, spacing / full_weight_spacing_m) (spacing: distance to the previous
 * point in scan order), along its surface normal when its neighbourhood is
 * line-like and equally in every direction otherwise (a corner, a pillar). */
struct TScanConstraint
{
	Eigen::Vector2d weakest = Eigen::Vector2d::UnitX();  //!< robot frame, unit: the least constrained direction
	double weakest_fraction = 0;  //!< share of the information along `weakest`, 0..0.5
	size_t points = 0;  //!< points with a neighbourhood (counted at all)
};

/** Normals are fitted (PCA) to the points in scan order within radius_m of
 * each point, at least 4 of them: over a fixed length of wall, range noise
 * tilts them by a few degrees. Normals fitted to the few nearest points of a
 * dense reference (ICP's geometric covariance, several keyframes of the same
 * wall within a centimetre) tilt by tens of degrees, and claimed 9 % of the
 * information along a bare corridor's axis (laser-only building, 8 m
 * scanner); this scan-order fit claims under 1 % there. */
TScanConstraint scanTranslationConstraint(const std::vector<mrpt::math::TPoint2D>& points, double radius_m,
										  double full_weight_spacing_m);

}  // namespace hslam::matching
