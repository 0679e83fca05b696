#include <hslam/fusion/se2.h>
#include <hslam/fusion/unscented_transform.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <stdexcept>

namespace hslam::fusion
{
namespace
{
bool isAngleIndex(Eigen::Index i) { return i % 3 == 2; }

Eigen::MatrixXd matrixSquareRoot(const Eigen::MatrixXd& m)
{
	Eigen::LLT<Eigen::MatrixXd> llt(m);
	if (llt.info() == Eigen::Success) return llt.matrixL();
	Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);  // semidefinite: clamp tiny negatives
	const Eigen::VectorXd roots = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
	return eig.eigenvectors() * roots.asDiagonal();
}
}  // namespace

TSigmaPoints makeSigmaPoints(const Eigen::VectorXd& mean, const Eigen::MatrixXd& cov, const TUnscentedParams& p)
{
	const Eigen::Index n = mean.size();
	const double lambda = p.alpha * p.alpha * (n + p.kappa) - n;  // eq. 74
	const Eigen::MatrixXd root = matrixSquareRoot((n + lambda) * cov);  // eq. 73
	TSigmaPoints s;
	s.points.resize(n, 2 * n + 1);
	s.points.col(0) = mean;
	for (Eigen::Index i = 0; i < n; ++i)
	{
		s.points.col(1 + i) = mean + root.col(i);
		s.points.col(1 + n + i) = mean - root.col(i);
	}
	for (Eigen::Index r = 0; r < n; ++r)
		if (isAngleIndex(r))
			for (Eigen::Index c = 0; c < s.points.cols(); ++c) s.points(r, c) = wrapToPi(s.points(r, c));
	s.meanWeights = Eigen::VectorXd::Constant(2 * n + 1, 1.0 / (2.0 * (n + lambda)));  // eq. 77
	s.covWeights = s.meanWeights;
	s.meanWeights[0] = lambda / (n + lambda);  // eq. 75
	s.covWeights[0] = lambda / (n + lambda) + (1.0 - p.alpha * p.alpha + p.beta);  // eq. 76
	return s;
}

Eigen::VectorXd poseVectorDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b)
{
	Eigen::VectorXd d = a - b;
	for (Eigen::Index i = 0; i < d.size(); ++i)
		if (isAngleIndex(i)) d[i] = wrapToPi(d[i]);
	return d;
}

Eigen::VectorXd poseVectorMean(const Eigen::MatrixXd& columns, const Eigen::VectorXd& weights)
{
	Eigen::VectorXd mean = columns * weights;
	for (Eigen::Index r = 0; r < columns.rows(); ++r)
	{
		if (!isAngleIndex(r)) continue;
		double s = 0, c = 0;
		for (Eigen::Index k = 0; k < columns.cols(); ++k)
		{
			s += weights[k] * std::sin(columns(r, k));
			c += weights[k] * std::cos(columns(r, k));
		}
		mean[r] = std::atan2(s, c);
	}
	return mean;
}

TTransformed unscentedTransform(const TSigmaPoints& sigma, const Eigen::VectorXd& inputMean, Eigen::Index crossRows,
								const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& f,
								const Eigen::VectorXd* centre)
{
	const Eigen::Index count = sigma.points.cols();
	Eigen::MatrixXd outputs;
	for (Eigen::Index k = 0; k < count; ++k)
	{
		const Eigen::VectorXd y = f(sigma.points.col(k));
		if (k == 0) outputs.resize(y.size(), count);
		outputs.col(k) = y;
	}
	TTransformed t;
	t.mean = centre ? *centre : poseVectorMean(outputs, sigma.meanWeights);
	t.cov = Eigen::MatrixXd::Zero(outputs.rows(), outputs.rows());
	t.crossCov = Eigen::MatrixXd::Zero(crossRows, outputs.rows());
	for (Eigen::Index k = 0; k < count; ++k)
	{
		const Eigen::VectorXd dy = poseVectorDifference(outputs.col(k), t.mean);
		const Eigen::VectorXd dx = poseVectorDifference(sigma.points.col(k), inputMean).head(crossRows);
		t.cov += sigma.covWeights[k] * dy * dy.transpose();
		t.crossCov += sigma.covWeights[k] * dx * dy.transpose();
	}
	return t;
}

}  // namespace hslam::fusion
