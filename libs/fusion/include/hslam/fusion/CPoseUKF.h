/* hslam: unscented Kalman filter for the planar robot pose (thesis 4.5.2-4.5.3,
 * eq. 73-77), fusing odometry (prediction) with scan matching (update).
 *
 * State: the current pose (x, y, theta) and, optionally, a "clone" of the pose
 * at the last matched scan (stochastic cloning). The clone lets a frame-to-
 * frame match (the pose change between the two scans, what the thesis' line
 * matcher measures) be fused as what it is, a relative measurement
 * h(X) = current (-) clone, with the correct correlations; a scan-to-map match
 * is an absolute measurement h(X) = current. The thesis fuses a relative
 * match as if it were absolute, which double-counts the previous pose error.
 *
 * Sigma points: 2n+1 points x +- columns of sqrt((n + lambda) P),
 * lambda = alpha^2 (n + kappa) - n (eq. 74), weights of eq. 75-77 with
 * beta = 2 for Gaussians. Angles are wrapped in every difference and averaged
 * on the circle, which solves the quadrant problem of thesis figure 113
 * without the +180 deg patch. Prediction keeps the noise-free composition
 * as the mean (see CPoseUKF.cpp: the sigma-point mean is biased towards the
 * centre of the arc when the heading is uncertain). After every step the covariance is symmetrised
 * and its eigenvalues floored so it stays positive definite. */
#pragma once

#include <hslam/fusion/se2.h>

#include <Eigen/Core>

#include <cmath>

namespace hslam::fusion
{
struct TUkfUpdateResult
{
	bool accepted = false;  //!< false: rejected by the gate, state unchanged
	double nis = 0;  //!< normalised innovation squared nu' S^-1 nu (chi-square, 3 dof)
	TPoseVec innovation = TPoseVec::Zero();  //!< z - h(x), angle wrapped
};

class CPoseUKF
{
   public:
	struct TOptions
	{
		double alpha = 0.5;  //!< sigma point spread (eq. 74); thesis: "usually a small number"
		double beta = 2.0;  //!< prior knowledge of the distribution; 2 is optimal for Gaussians (eq. 76)
		double kappa = 0.0;  //!< secondary scaling (eq. 74)

		template <class V>
		void visit(V& v)
		{
			v.real("alpha", alpha, 1e-3, 1.0);
			v.real("beta", beta, 0.0, 10.0);
			v.real("kappa", kappa, 0.0, 10.0);
		}
	};

	CPoseUKF() : CPoseUKF(TOptions()) {}
	explicit CPoseUKF(const TOptions& options);

	/** Starts from `pose` with covariance `cov`; drops any clone. */
	void reset(const TPoseVec& pose, const Eigen::Matrix3d& cov);

	/** Prediction: current <- current (+) (increment + noise), the noise having
	 * covariance incrementCov in the robot frame (odometry noise model). The
	 * predicted heading variance is kept at most the uniform circle's
	 * (kUniformCircleHeadingVariance): a wider noise is scaled down to it. */
	void predict(const TPoseVec& increment, const Eigen::Matrix3d& incrementCov);

	/** Scales the current pose's covariance by `factor` (>= 1) and its
	 * correlation with the clone by sqrt(factor): the prediction is declared
	 * less certain than the motion model said (a refused match the scan
	 * shows to be right, CScanMatchingPoseEstimator). */
	void inflateCurrentPoseCovariance(double factor);

	/** Stores the current pose as the anchor of the next relative measurement. */
	void cloneCurrentPose();
	bool hasClone() const { return m_x.size() == 6; }

	/** Absolute pose measurement z of the current pose with covariance R.
	 * Rejected (state unchanged) if its NIS exceeds gateNis. */
	TUkfUpdateResult updateAbsolute(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis);
	/** NIS an absolute measurement z with covariance R would have now
	 * (identity measurement: S = P + R exactly), without updating. */
	double absoluteNis(const TPoseVec& z, const Eigen::Matrix3d& R) const;
	/** Relative measurement z = current pose expressed in the clone's frame.
	 * Requires hasClone(). */
	TUkfUpdateResult updateRelative(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis);

	TPoseVec pose() const { return m_x.head<3>(); }
	/** The cloned pose (requires hasClone()). */
	TPoseVec clonePose() const { return m_x.tail<3>(); }
	Eigen::Matrix3d covariance() const { return m_P.topLeftCorner<3, 3>(); }
	const TOptions& options() const { return m_options; }

	/** pi^2 / 3: the variance of a heading uniform on the circle, the widest
	 * the sigma points can carry without wrapping onto the mean. */
	static constexpr double kUniformCircleHeadingVariance = M_PI * M_PI / 3.0;

   private:
	void capHeadingNoise(Eigen::MatrixXd& augCov, Eigen::Index n) const;
	template <class Measurement>
	TUkfUpdateResult update(const TPoseVec& z, const Eigen::Matrix3d& R, double gateNis, Measurement h);
	void keepPositiveDefinite();

	TOptions m_options;
	Eigen::VectorXd m_x;  //!< [current pose] or [current pose; clone]
	Eigen::MatrixXd m_P;
};

}  // namespace hslam::fusion
