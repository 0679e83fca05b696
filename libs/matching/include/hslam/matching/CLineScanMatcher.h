/* hslam: the thesis' feature-based scan matcher (4.4.2 iii, figures 89-90,
 * 114-115, eq. 65-72), between two consecutive scans.
 *
 * 1. Pair lines (line_pairing.h).
 * 2. Rotation: each pair i gives phi_i = alpha_prev - alpha_cur (normal
 *    angles, wrapped to (-pi, pi], so the quadrant change of figure 113 needs
 *    no +180 deg patch). Gaussian weight around the odometry rotation phi_o
 *    (eq. 66): w_i = exp(-(phi_i - phi_o)^2 / (2 sigma^2)); the thesis writes
 *    the denominator as 18 deg^2, i.e. sigma = 3 deg, tuned for 5 deg steps;
 *    here sigma^2 = (3 deg)^2 + the odometry rotation variance, so the weight
 *    stays meaningful for large steps (and the pairing gates widen to 3 sigma). phi = phi_o + weighted
 *    mean of (phi_i - phi_o). If the best weight is below 0.9 the match is
 *    weak (figure 115: "likely to be erroneous").
 * 3. Translation by weighted least squares (eq. 72) over the line offsets.
 *    Eq. 70-71 (dc = m dx - dy) break down for near-vertical lines (the thesis
 *    says so in 4.5.5); in normal form the same relation is exact for every
 *    orientation: rho_cur = rho_prev - n_prev . t, so each pair gives one row
 *    n_prev . t = rho_prev - rho_cur. Directions no line constrains (a
 *    corridor's axis) keep the odometry translation, with its uncertainty.
 * 4. Fallback (figure 115 b): with fewer than min_pairs_for_lines pairs, or
 *    when the line result is further from odometry than the point-based
 *    estimate (point_translation.h), the point-based translation is used.
 *
 * Output: the pose of the current scan in the previous robot frame, its
 * covariance (from the weighted residuals) and a quality flag. */
#pragma once

#include <hslam/features/line_segment.h>
#include <hslam/matching/line_pairing.h>
#include <hslam/matching/match_result.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::matching
{
/** What the matcher needs of one scan. */
struct TLineScanFrame
{
	features::TLineSegmentList lines;  //!< robot frame
	std::vector<mrpt::math::TPoint2D> points;  //!< valid points, robot frame (for the point fallback)
	mrpt::maps::CSimplePointsMap pointsMap;  //!< the same points, k-d tree for the fallback
};

class CLineScanMatcher
{
   public:
	struct TOptions
	{
		TLinePairingOptions pairing;
		double rotation_weight_sigma_rad = 3.0 * M_PI / 180.0;  //!< eq. 66: 2 sigma^2 = 18 deg^2
		double weak_weight = 0.9;  //!< best weight below this: weak match (figure 115)
		int min_pairs_for_lines = 3;  //!< fewer pairs: point-based translation (thesis: "2 or less")
		double min_constraint_sin = 0.34;  //!< sin of the smallest angle between constraining lines (20 deg)
		double min_translation_std_m = 0.01;  //!< floor of the translation std (laser noise)
		double min_rotation_std_rad = 0.25 * M_PI / 180.0;  //!< floor of the rotation std
		bool prefer_closer_to_odometry = true;  //!< thesis figure 115 b rule between line and point results
		double point_start_gate_m = 0.5;  //!< point fallback: first association gate
		double point_end_gate_m = 0.1;  //!< point fallback: last association gate
		int point_iterations = 8;
		/** The translation's covariance also carries each paired line's own
		 * rho variance (its TLS fit, TLineSegment::var_rho_m2, floored by
		 * min_translation_std_m) through the least squares of eq. 72: a
		 * direction that only a short, sparse or far line constrains is as
		 * loose as that line's rho, whatever the residuals say (a corridor's
		 * axis seen through a far end wall). */
		bool rho_variance_covariance = true;

		template <class V>
		void visit(V& v)
		{
			pairing.visit(v);
			v.degrees("rotation_weight_sigma_deg", rotation_weight_sigma_rad, 0.1, 90.0);
			v.real("weak_weight", weak_weight, 0.0, 1.0);
			v.integer("min_pairs_for_lines", min_pairs_for_lines, 1, 100);
			v.real("min_constraint_sin", min_constraint_sin, 0.01, 1.0);
			v.real("min_translation_std_m", min_translation_std_m, 1e-4, 1.0);
			v.degrees("min_rotation_std_deg", min_rotation_std_rad, 0.001, 10.0);
			v.flag("prefer_closer_to_odometry", prefer_closer_to_odometry);
			v.real("point_start_gate_m", point_start_gate_m, 0.01, 5.0);
			v.real("point_end_gate_m", point_end_gate_m, 0.01, 5.0);
			v.integer("point_iterations", point_iterations, 1, 100);
			v.flag("rho_variance_covariance", rho_variance_covariance);
		}
	};

	CLineScanMatcher() : CLineScanMatcher(TOptions()) {}
	explicit CLineScanMatcher(const TOptions& options) : m_options(options) {}

	/** Pose of `current` in the robot frame of `previous`; `odometry` is the
	 * predicted pose change and `odometryCov` its covariance. */
	TPoseMatch match(const TLineScanFrame& previous, const TLineScanFrame& current, const mrpt::poses::CPose2D& odometry,
					 const Eigen::Matrix3d& odometryCov) const;

	const TOptions& options() const { return m_options; }

   private:
	struct TRotation
	{
		double phi_rad = 0, variance = 0, bestWeight = 0;
		std::vector<double> weights;  //!< per pair, normalised to sum 1
	};
	struct TTranslation
	{
		Eigen::Vector2d t = Eigen::Vector2d::Zero();
		Eigen::Matrix2d cov = Eigen::Matrix2d::Identity();
		bool fullyConstrained = false;
	};

	TRotation estimateRotation(const TLineScanFrame& previous, const TLineScanFrame& current,
							   const std::vector<TLinePair>& pairs, double odometryPhi, double odometryPhiStd) const;
	TTranslation estimateLineTranslation(const TLineScanFrame& previous, const TLineScanFrame& current,
										 const std::vector<TLinePair>& pairs, const TRotation& rotation,
										 const Eigen::Vector2d& odometryT, const Eigen::Matrix2d& odometryTCov) const;

	TOptions m_options;
};

}  // namespace hslam::matching
