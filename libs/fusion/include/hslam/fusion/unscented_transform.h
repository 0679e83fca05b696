/* hslam: the unscented transform (thesis 4.5.2, eq. 73-77) for vectors made
 * of stacked planar poses: every third component (index 2, 5, ...) is an
 * angle, wrapped in differences and averaged on the circle. */
#pragma once

#include <Eigen/Core>

#include <functional>

namespace hslam::fusion
{
struct TUnscentedParams
{
	double alpha = 0.5, beta = 2.0, kappa = 0.0;
};

struct TSigmaPoints
{
	Eigen::MatrixXd points;  //!< one sigma point per column (2n+1 columns)
	Eigen::VectorXd meanWeights, covWeights;
};

/** Sigma points of N(mean, cov); columns of sqrt((n + lambda) cov) from a
 * Cholesky factor (eigen-decomposition fallback if cov is only semidefinite). */
TSigmaPoints makeSigmaPoints(const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov, const TUnscentedParams& p);

/** a - b with every pose angle (index % 3 == 2) wrapped to (-pi, pi]. */
Eigen::VectorXd poseVectorDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

/** Weighted mean of stacked-pose columns, angles averaged on the circle. */
Eigen::VectorXd poseVectorMean(const Eigen::MatrixXd& columns, const Eigen::VectorXd& weights);

struct TTransformed
{
	Eigen::VectorXd mean;
	Eigen::MatrixXd cov;  //!< of the outputs
	Eigen::MatrixXd crossCov;  //!< inputs x outputs, from the first `crossRows` input components
};

/** Propagates sigma points through f and returns the outputs' mean,
 * covariance and cross-covariance with the first crossRows inputs. If
 * `centre` is given, it is used as the output mean (and the covariances are
 * taken around it) instead of the sigma points' weighted mean. */
TTransformed unscentedTransform(const TSigmaPoints& sigma, const Eigen::VectorXd& inputMean, Eigen::Index crossRows,
								const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
								const Eigen::VectorXd* centre = nullptr);

}  // namespace hslam::fusion
