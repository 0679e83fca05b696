#include <hslam/fusion/se2.h>
#include <hslam/matching/CLineScanMatcher.h>
#include <hslam/matching/point_translation.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace hslam::matching
{
using fusion::wrapToPi;

namespace
{
/** Rotation implied by one pair relative to the odometry rotation, wrapped;
 * a pair seen from the other side (normal flipped) is turned back by pi. */
double pairRotationOffset(double alphaPrev, double alphaCur, double odometryPhi)
{
	double d = wrapToPi(alphaPrev - alphaCur - odometryPhi);
	if (std::abs(d) > M_PI / 2) d = wrapToPi(d + M_PI);
	return d;
}

/** rho of the current line expressed with the normal that matches the previous line's. */
double alignedCurrentRho(double alphaPrev, double alphaCur, double rhoCur, double phi)
{
	return std::abs(wrapToPi(alphaPrev - alphaCur - phi)) > M_PI / 2 ? -rhoCur : rhoCur;
}

/** Variance of b = rho_prev - rho_cur of one pair: the two lines' own TLS
 * fit variances (TLineSegment::var_rho_m2), each floored by floor2. */
double offsetVariance(const features::TLineSegment& prev, const features::TLineSegment& cur, double floor2)
{
	return std::max(prev.var_rho_m2, floor2) + std::max(cur.var_rho_m2, floor2);
}

/** Covariance of t = H^-1 sum w_i n_i b_i (eq. 72) that the variances of the
 * b_i alone cause: H^-1 (sum w_i^2 var(b_i) n_i n_i^T) H^-1; with a loose
 * direction (not fully constrained), only along the constrained one, v. */
Eigen::Matrix2d propagatedOffsetCovariance(const std::vector<Eigen::Vector2d>& normals,
										   const std::vector<double>& weights, const std::vector<double>& variances,
										   const Eigen::Matrix2d& H, bool fullyConstrained, const Eigen::Vector2d& v,
										   double lambda)
{
	Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
	for (size_t i = 0; i < normals.size(); ++i)
		M += weights[i] * weights[i] * variances[i] * normals[i] * normals[i].transpose();
	if (fullyConstrained)
	{
		const Eigen::Matrix2d Hi = H.inverse();
		return Hi * M * Hi;
	}
	return v * v.transpose() * (v.dot(M * v) / std::max(lambda * lambda, 1e-18));
}

double effectiveCount(const std::vector<double>& normalisedWeights)
{
	double sq = 0;
	for (double w : normalisedWeights) sq += w * w;
	return sq > 0 ? 1.0 / sq : 0.0;
}
}  // namespace

CLineScanMatcher::TRotation CLineScanMatcher::estimateRotation(const TLineScanFrame& prev, const TLineScanFrame& cur,
															   const std::vector<TLinePair>& pairs,
															   double odometryPhi, double odometryPhiStd) const
{
	TRotation r;
	std::vector<double> offsets;
	for (const auto& p : pairs)
		offsets.push_back(pairRotationOffset(prev.lines[p.previous].alpha_rad, cur.lines[p.current].alpha_rad, odometryPhi));
	// eq. 66 with the odometry's own rotation uncertainty added to the width.
	const double twoSigma2 =
		2 * (m_options.rotation_weight_sigma_rad * m_options.rotation_weight_sigma_rad + odometryPhiStd * odometryPhiStd);
	// Pass 1 (eq. 66): Gaussian weights around the odometry rotation.
	double centre = 0;
	for (int pass = 0; pass < 2; ++pass)
	{
		std::vector<double> w(offsets.size());
		double sum = 0, weighted = 0;
		for (size_t i = 0; i < offsets.size(); ++i)
		{
			w[i] = std::exp(-std::pow(offsets[i] - centre, 2) / twoSigma2);
			sum += w[i];
			weighted += w[i] * offsets[i];
			if (pass == 0) r.bestWeight = std::max(r.bestWeight, w[i]);
		}
		if (sum < 1e-6) return r;  // no pair agrees with odometry: rotation unknown
		for (double& wi : w) wi /= sum;
		// Pass 2 re-centres the weights on the pass-1 estimate (one mean-shift
		// step), so a few degrees of odometry error do not bias the result
		// towards odometry; the quality flag still uses the pass-1 weights.
		centre = weighted / sum;
		r.weights = w;
	}
	r.phi_rad = wrapToPi(odometryPhi + centre);
	double spread = 0;
	for (size_t i = 0; i < offsets.size(); ++i) spread += r.weights[i] * std::pow(offsets[i] - centre, 2);
	const double floor2 = m_options.min_rotation_std_rad * m_options.min_rotation_std_rad;
	r.variance = std::max(spread, floor2) / std::max(1.0, effectiveCount(r.weights));
	r.variance = std::max(r.variance, floor2);
	return r;
}

CLineScanMatcher::TTranslation CLineScanMatcher::estimateLineTranslation(
	const TLineScanFrame& prev, const TLineScanFrame& cur, const std::vector<TLinePair>& pairs, const TRotation& rot,
	const Eigen::Vector2d& odometryT, const Eigen::Matrix2d& odometryTCov) const
{
	// Weighted least squares (eq. 72) on rows n_prev . t = rho_prev - rho_cur.
	Eigen::Matrix2d H = Eigen::Matrix2d::Zero();
	Eigen::Vector2d g = Eigen::Vector2d::Zero();
	std::vector<Eigen::Vector2d> normals;
	std::vector<double> offsets, variances;
	const double floor2 = m_options.min_translation_std_m * m_options.min_translation_std_m;
	for (size_t i = 0; i < pairs.size(); ++i)
	{
		const auto& lp = prev.lines[pairs[i].previous];
		const auto& lc = cur.lines[pairs[i].current];
		const Eigen::Vector2d n(std::cos(lp.alpha_rad), std::sin(lp.alpha_rad));
		const double b = lp.rho_m - alignedCurrentRho(lp.alpha_rad, lc.alpha_rad, lc.rho_m, rot.phi_rad);
		H += rot.weights[i] * n * n.transpose();
		g += rot.weights[i] * n * b;
		normals.push_back(n);
		offsets.push_back(b);
		variances.push_back(offsetVariance(lp, lc, floor2));
	}
	TTranslation tr;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(H);  // weights sum to 1
	const Eigen::Vector2d lambda = eig.eigenvalues();  // ascending
	const Eigen::Matrix2d V = eig.eigenvectors();
	const double s = m_options.min_constraint_sin;
	const double minLambda = 0.5 * (1.0 - std::sqrt(1.0 - s * s));  // two lines at asin(s) apart
	tr.fullyConstrained = lambda[0] >= minLambda;
	if (tr.fullyConstrained)
		tr.t = H.inverse() * g;
	else  // constrained direction V.col(1) from the lines, the other from odometry
		tr.t = V.col(0) * V.col(0).dot(odometryT) + V.col(1) * (V.col(1).dot(g) / std::max(lambda[1], 1e-9));
	double residual2 = 0;
	for (size_t i = 0; i < normals.size(); ++i) residual2 += rot.weights[i] * std::pow(normals[i].dot(tr.t) - offsets[i], 2);
	const double sigma2 = std::max(residual2, floor2) / std::max(1.0, effectiveCount(rot.weights));
	if (tr.fullyConstrained)
		tr.cov = sigma2 * H.inverse();
	else
		tr.cov = V.col(0) * V.col(0).transpose() * V.col(0).dot(odometryTCov * V.col(0)) +
				 V.col(1) * V.col(1).transpose() * sigma2 / std::max(lambda[1], 1e-9);
	// The residuals cannot tell how well a direction that one line alone
	// constrains is measured (its residual is zero): the lines' own fits can.
	if (m_options.rho_variance_covariance)
		tr.cov += propagatedOffsetCovariance(normals, rot.weights, variances, H, tr.fullyConstrained, V.col(1), lambda[1]);
	return tr;
}

TPoseMatch CLineScanMatcher::match(const TLineScanFrame& prev, const TLineScanFrame& cur,
								   const mrpt::poses::CPose2D& odometry, const Eigen::Matrix3d& odometryCov) const
{
	TPoseMatch result;
	result.method = "lines";
	// Gates and weights widen with the odometry uncertainty (3 sigma): the
	// thesis' fixed values assume 0.1 m / 5 deg steps of good odometry.
	TLinePairingOptions pairing = m_options.pairing;
	const double odoThetaStd = std::sqrt(std::max(0.0, odometryCov(2, 2)));
	const double odoXyStd = std::sqrt(std::max(0.0, std::max(odometryCov(0, 0), odometryCov(1, 1))));
	pairing.max_angle_diff_rad = std::max(pairing.max_angle_diff_rad, 3.0 * odoThetaStd);
	pairing.max_rho_diff_m = std::max(pairing.max_rho_diff_m, 3.0 * odoXyStd);
	const auto pairs = pairLines(prev.lines, cur.lines, odometry, pairing);
	result.correspondences = pairs.size();
	if (pairs.empty()) return result;  // failed: nothing to match (thesis: keep odometry)
	const TRotation rot = estimateRotation(prev, cur, pairs, odometry.phi(), odoThetaStd);
	result.score = rot.bestWeight;
	if (rot.weights.empty()) return result;  // no pair agrees with odometry

	const Eigen::Vector2d odoT(odometry.x(), odometry.y());
	const Eigen::Matrix2d odoTCov = odometryCov.topLeftCorner<2, 2>();
	TTranslation tr = estimateLineTranslation(prev, cur, pairs, rot, odoT, odoTCov);
	bool usedPoints = false;
	if (!cur.points.empty() && prev.pointsMap.size() > 0 &&
		(static_cast<int>(pairs.size()) < m_options.min_pairs_for_lines || m_options.prefer_closer_to_odometry))
	{
		const auto pts = estimatePointTranslation(prev.pointsMap, cur.points, rot.phi_rad, tr.t,
												  m_options.point_start_gate_m, m_options.point_end_gate_m,
												  m_options.point_iterations);
		const bool fewLines = static_cast<int>(pairs.size()) < m_options.min_pairs_for_lines;
		const bool pointsCloser =
			m_options.prefer_closer_to_odometry && (pts.translation_m - odoT).norm() < (tr.t - odoT).norm();
		if (pts.inliers >= 10 && (fewLines || pointsCloser))
		{
			tr.t = pts.translation_m;
			tr.cov = pts.covariance;
			usedPoints = true;
		}
	}
	result.pose = mrpt::poses::CPose2D(tr.t.x(), tr.t.y(), rot.phi_rad);
	result.covariance.setZero();
	result.covariance.topLeftCorner<2, 2>() = tr.cov;
	result.covariance(2, 2) = rot.variance;
	result.method = usedPoints ? "lines:points" : "lines";
	const bool weak = rot.bestWeight < m_options.weak_weight || (!tr.fullyConstrained && !usedPoints) ||
					  static_cast<int>(pairs.size()) < m_options.min_pairs_for_lines;
	result.quality = weak ? EMatchQuality::weak : EMatchQuality::good;
	return result;
}

}  // namespace hslam::matching
