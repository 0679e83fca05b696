#include <hslam/fusion/CPoseUKF.h>
#include <hslam/fusion/unscented_transform.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hslam::fusion
{
namespace
{
constexpr double kMinEigenvalue = 1e-12;  // keeps P positive definite
}

CPoseUKF::CPoseUKF(const TOptions& options) : m_options(options) { reset(TPoseVec::Zero(), Eigen::Matrix3d::Zero()); }

void CPoseUKF::reset(const TPoseVec& pose, const Eigen::Matrix3d& cov)
{
	m_x = pose;
	m_P = cov;
	keepPositiveDefinite();
}

void CPoseUKF::inflateCurrentPoseCovariance(double factor)
{
	if (!(factor > 1.0)) return;
	const double root = std::sqrt(factor);
	m_P.topLeftCorner<3, 3>() *= factor;
	if (hasClone())
	{
		m_P.topRightCorner<3, 3>() *= root;
		m_P.bottomLeftCorner<3, 3>() *= root;
	}
	keepPositiveDefinite();
}

void CPoseUKF::predict(const TPoseVec& increment, const Eigen::Matrix3d& incrementCov)
{
	// Augmented state [X; w], w ~ N(0, incrementCov) the odometry noise.
	const Eigen::Index n = m_x.size();
	Eigen::VectorXd augMean = Eigen::VectorXd::Zero(n + 3);
	augMean.head(n) = m_x;
	Eigen::MatrixXd augCov = Eigen::MatrixXd::Zero(n + 3, n + 3);
	augCov.topLeftCorner(n, n) = m_P;
	augCov.bottomRightCorner<3, 3>() = incrementCov;
	capHeadingNoise(augCov, n);
	const auto sigma = makeSigmaPoints(augMean, augCov, {m_options.alpha, m_options.beta, m_options.kappa});
	const auto motion = [&](const Eigen::VectorXd& a) -> Eigen::VectorXd {
		Eigen::VectorXd next = a.head(n);
		next.head<3>() = compose(a.head<3>(), increment + a.tail<3>());
		return next;
	};
	// The mean is the noise-free composition, not the sigma points' weighted
	// mean: with a wide heading distribution (relative-only matching never
	// bounds the absolute heading variance) the weighted mean of the rotated
	// positions lies inside the arc, shortening every step (measured on aces:
	// -7 cm per 1 m step). The UT still gives the covariance, around this mean.
	const Eigen::VectorXd noiseFree = motion(augMean);
	const auto t = unscentedTransform(sigma, augMean, 0, motion, &noiseFree);
	m_x = t.mean;
	m_P = t.cov;
	keepPositiveDefinite();
}

void CPoseUKF::capHeadingNoise(Eigen::MatrixXd& augCov, Eigen::Index n) const
{
	// A heading std beyond the uniform circle's (pi / sqrt(3), 104 deg) says
	// nothing more, and the sigma points, sqrt(n + lambda) std apart (1.5
	// with the defaults), wrap round the circle and fold back onto the mean:
	// intel without odometry, t = 947 s, the constant-velocity prior's 245 deg
	// (8 s since the last scan) came out of the transform as 7 deg, and the
	// filter refused the right match at NIS 477. The noise's heading is scaled
	// (with its correlations) so that the predicted heading variance stays at
	// most the uniform circle's.
	const double room = std::max(0.0, kUniformCircleHeadingVariance - m_P(2, 2));
	const double noise = augCov(n + 2, n + 2);
	if (!(noise > room)) return;
	const double scale = std::sqrt(room / noise);
	augCov.row(n + 2) *= scale;
	augCov.col(n + 2) *= scale;
}

void CPoseUKF::cloneCurrentPose()
{
	const Eigen::Vector3d current = m_x.head<3>();
	const Eigen::Matrix3d Pcc = m_P.topLeftCorner<3, 3>();
	m_x.resize(6);
	m_x << current, current;
	m_P.resize(6, 6);
	m_P << Pcc, Pcc, Pcc, Pcc;  // the clone is perfectly correlated with the current pose
	keepPositiveDefinite();
}

template <class Measurement>
TUkfUpdateResult CPoseUKF::update(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis, Measurement h)
{
	const Eigen::Index n = m_x.size();
	const auto sigma = makeSigmaPoints(m_x, m_P, {m_options.alpha, m_options.beta, m_options.kappa});
	// Predicted measurement: h at the mean, for the same reason as in predict()
	// (the sigma-point mean of a relative pose shrinks when headings are
	// uncertain); S and Pxz come from the sigma points around it.
	const Eigen::VectorXd predicted = h(m_x);
	const auto t = unscentedTransform(sigma, m_x, n, h, &predicted);
	const Eigen::Matrix3d S = t.cov + R;
	TUkfUpdateResult result;
	result.innovation = poseVectorDifference(z, t.mean);
	const Eigen::LDLT<Eigen::Matrix3d> Sinv(S);
	result.nis = result.innovation.dot(Sinv.solve(result.innovation));
	if (!(result.nis <= gateNis)) return result;  // also rejects NaN
	const Eigen::MatrixXd K = Sinv.solve(t.crossCov.transpose()).transpose();  // Pxz S^-1
	m_x = m_x + K * result.innovation;
	for (Eigen::Index i = 2; i < n; i += 3) m_x[i] = wrapToPi(m_x[i]);
	m_P = m_P - K * S * K.transpose();
	keepPositiveDefinite();
	result.accepted = true;
	return result;
}

TUkfUpdateResult CPoseUKF::updateAbsolute(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis)
{
	return update(z, R, gateNis, [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return x.head<3>(); });
}

double CPoseUKF::absoluteNis(const TPoseVec& z, const Eigen::Matrix3d& R) const
{
	TPoseVec nu = z - m_x.head<3>();
	nu[2] = wrapToPi(nu[2]);
	return nu.dot((covariance() + R).ldlt().solve(nu));
}

TUkfUpdateResult CPoseUKF::updateRelative(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis)
{
	if (!hasClone()) throw std::logic_error("CPoseUKF::updateRelative without a cloned pose");
	return update(z, R, gateNis,
				  [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return inverseCompose(x.head<3>(), x.tail<3>()); });
}

void CPoseUKF::keepPositiveDefinite()
{
	m_P = 0.5 * (m_P + m_P.transpose());
	Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m_P);
	if (eig.eigenvalues().minCoeff() >= kMinEigenvalue) return;
	const Eigen::VectorXd clamped = eig.eigenvalues().cwiseMax(kMinEigenvalue);
	m_P = eig.eigenvectors() * clamped.asDiagonal() * eig.eigenvectors().transpose();
}

}  // namespace hslam::fusion
