/* hslam: a straight wall segment extracted from one laser scan (thesis
 * 4.4.2 i-ii, eq. 57-64).
 *
 * The thesis stores a line as slope/intercept (y = m x + c, eq. 63-64) and
 * notes that this form breaks down for walls near 90 deg. Here the line is
 * kept in normal form (rho, alpha): every point p on it satisfies
 *     p.x cos(alpha) + p.y sin(alpha) = rho,   rho >= 0,
 * which is finite for every orientation. The thesis quantities stay derivable
 * (slopeIntercept(), directionAngle()). */
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace hslam::features
{
struct TLineSegment
{
	/** Endpoints in the robot frame (m): the fitted line's projections of the
	 * first and last point of the segment, in beam order. */
	mrpt::math::TPoint2D p0, p1;
	double rho_m = 0;  //!< distance of the infinite line from the robot origin (m), >= 0
	double alpha_rad = 0;  //!< direction of the line's normal, (-pi, pi]
	size_t first_beam = 0;  //!< index of the first beam of the segment in its scan
	size_t last_beam = 0;  //!< index of the last beam (inclusive)
	size_t point_count = 0;  //!< valid points used in the fit
	double fit_rms_m = 0;  //!< RMS orthogonal distance of those points to the line (m)
	/** True if the wall may continue beyond p0 unseen, so p0 is not a wall
	 * end: the beam just outside the segment is invalid, outside the scan, or
	 * hits something in front of the line (occlusion). False at a corner or
	 * where that beam sees past the line (the wall really ends). Set by every
	 * extractor (segment_ops.h markOccludedEnds). */
	bool p0_occluded = false;
	bool p1_occluded = false;  //!< the same for p1
	/** Covariance of (rho_m, alpha_rad) of the TLS fit, from its residuals
	 * (line_fit.h). Zero for noiseless points: floor it with the sensor noise
	 * (e.g. scan.stdError) before using it as a weight. */
	double var_rho_m2 = 0, var_alpha_rad2 = 0, cov_rho_alpha_m_rad = 0;

	double length_m() const;
	/** Direction of p0 -> p1 (rad, (-pi, pi]); the thesis' "gradient" as an angle. */
	double directionAngle_rad() const;
	mrpt::math::TPoint2D midpoint() const;
	/** Thesis eq. 63-64 (y = m x + c); nullopt for a vertical line (|sin alpha| < 1e-6). */
	std::optional<std::pair<double, double>> slopeIntercept() const;
	/** Signed orthogonal distance of p to the infinite line (m). */
	double distanceTo(const mrpt::math::TPoint2D& p) const;
};

using TLineSegmentList = std::vector<TLineSegment>;

}  // namespace hslam::features
