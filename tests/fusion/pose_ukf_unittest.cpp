/* UKF of thesis 4.5 (CPoseUKF): behaviour with hand-derived expectations. */
#include <gtest/gtest.h>
#include <hslam/fusion/CAdaptiveMeasurementNoise.h>
#include <hslam/fusion/CPoseUKF.h>
#include <hslam/fusion/odometry_noise.h>
#include <hslam/fusion/unscented_transform.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

using namespace hslam::fusion;

namespace
{
Eigen::Matrix3d diag(double sxy, double sth) { return Eigen::Vector3d(sxy * sxy, sxy * sxy, sth * sth).asDiagonal(); }

bool isSymmetricPositiveDefinite(const Eigen::MatrixXd& P)
{
	if ((P - P.transpose()).norm() > 1e-12) return false;
	return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff() > 0;
}
}  // namespace

TEST(PoseUKF, StaticRobotStaysPutAndCovarianceSettles)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec::Zero(), diag(0.01, 0.01));
	std::mt19937 rng(1);
	std::normal_distribution<double> noise(0, 0.02);
	double lastTrace = 0;
	for (int k = 0; k < 200; ++k)
	{
		ukf.predict(TPoseVec::Zero(), diag(0.002, 0.002));
		const TPoseVec z(noise(rng), noise(rng), 0.5 * noise(rng));
		ASSERT_TRUE(ukf.updateAbsolute(z, diag(0.02, 0.01), 1e9).accepted);
		lastTrace = ukf.covariance().trace();
	}
	EXPECT_LT(ukf.pose().head<2>().norm(), 0.02);  // averages 200 noisy readings of the origin
	EXPECT_LT(std::abs(ukf.pose()[2]), 0.01);
	// steady state of a random walk (q) measured with r: p = q/2 + sqrt(q^2/4 + q r) per axis
	const double q = 0.002 * 0.002, r = 0.02 * 0.02;
	EXPECT_NEAR(ukf.covariance()(0, 0), q / 2 + std::sqrt(q * q / 4 + q * r), 2e-5);
	EXPECT_GT(lastTrace, 0);
}

TEST(PoseUKF, CovarianceGrowsWithoutMeasurementsAndShrinksWithThem)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec::Zero(), diag(0.01, 0.01));
	double trace = ukf.covariance().trace();
	for (int k = 0; k < 10; ++k)
	{
		ukf.predict(TPoseVec(0.1, 0, 0.05), diag(0.02, 0.02));
		EXPECT_GT(ukf.covariance().trace(), trace);
		trace = ukf.covariance().trace();
	}
	const TPoseVec truth = ukf.pose();
	ukf.updateAbsolute(truth, diag(0.01, 0.005), 1e9);
	EXPECT_LT(ukf.covariance().trace(), 0.5 * trace);
	EXPECT_TRUE(isSymmetricPositiveDefinite(ukf.covariance()));
}

TEST(PoseUKF, PredictionMeanIsTheComposition)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec(1, 2, M_PI / 2), diag(0.1, 0.5));  // very uncertain heading
	ukf.predict(TPoseVec(1.0, 0, 0.1), diag(0.05, 0.05));
	EXPECT_NEAR(ukf.pose()[0], 1.0, 1e-12);
	EXPECT_NEAR(ukf.pose()[1], 3.0, 1e-12);  // a full metre, not shortened by the heading spread
	EXPECT_NEAR(ukf.pose()[2], M_PI / 2 + 0.1, 1e-12);
	// the heading uncertainty turned into lateral (x) uncertainty: ~ (1 m * 0.5 rad)^2
	EXPECT_GT(ukf.covariance()(0, 0), 0.15);
}

TEST(PoseUKF, AnglesAreWrappedAcrossPi)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec(0, 0, M_PI - 0.05), diag(0.01, 0.05));
	ukf.predict(TPoseVec(0, 0, 0.1), diag(0.001, 0.001));
	EXPECT_NEAR(ukf.pose()[2], -M_PI + 0.05, 1e-9);
	// a measurement on the other side of +-pi pulls the estimate the short way
	const auto r = ukf.updateAbsolute(TPoseVec(0, 0, M_PI - 0.05), diag(0.01, 0.05), 1e9);
	EXPECT_LT(std::abs(r.innovation[2]), 0.2);
	EXPECT_GT(std::abs(ukf.pose()[2]), M_PI - 0.1);
}

TEST(PoseUKF, RelativeMeasurementAgainstTheCloneCorrectsTheIncrement)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec(5, -2, 1.0), diag(0.5, 0.3));  // large absolute uncertainty
	ukf.cloneCurrentPose();
	ukf.predict(TPoseVec(1.0, 0.0, 0.2), diag(0.1, 0.1));  // odometry says 1 m, 0.2 rad
	const TPoseVec measured(0.9, 0.05, 0.15);  // the scan matcher says otherwise, precisely
	const auto r = ukf.updateRelative(measured, diag(0.005, 0.002), 1e9);
	ASSERT_TRUE(r.accepted);
	const TPoseVec relative = inverseCompose(ukf.pose(), ukf.clonePose());
	EXPECT_NEAR(relative[0], 0.9, 0.01);
	EXPECT_NEAR(relative[1], 0.05, 0.01);
	EXPECT_NEAR(relative[2], 0.15, 0.005);
	// a relative measurement cannot remove the absolute uncertainty of the anchor
	EXPECT_GT(ukf.covariance()(0, 0), 0.2);
}

TEST(PoseUKF, GateRejectsAnOutlierAndLeavesTheStateUnchanged)
{
	CPoseUKF ukf;
	ukf.reset(TPoseVec::Zero(), diag(0.05, 0.02));
	const auto before = ukf.pose();
	const auto r = ukf.updateAbsolute(TPoseVec(3.0, 0, 0), diag(0.05, 0.02), 16.27);
	EXPECT_FALSE(r.accepted);
	EXPECT_GT(r.nis, 1000);
	EXPECT_EQ(ukf.pose(), before);
}

TEST(UnscentedTransform, LinearFunctionIsExact)
{
	Eigen::VectorXd mean(3);
	mean << 1, 2, 0.3;
	Eigen::MatrixXd cov = diag(0.2, 0.1);
	cov(0, 1) = cov(1, 0) = 0.01;
	const auto sigma = makeSigmaPoints(mean, cov, {});
	EXPECT_NEAR(sigma.meanWeights.sum(), 1.0, 1e-12);
	const auto t = unscentedTransform(sigma, mean, 3, [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return x; });
	EXPECT_LT((t.mean - mean).norm(), 1e-12);
	EXPECT_LT((t.cov - cov).norm(), 1e-12);
}

TEST(OdometryNoise, ThesisEquations78to80)
{
	TOdometryNoiseOptions o;
	o.model = "thesis";
	o.min_xy_std_m = o.min_theta_std_rad = 1e-6;
	const auto c = odometryIncrementCovariance(o, TPoseVec(0.5, 0, 0.2));
	EXPECT_NEAR(c(0, 0), 0.5 * 0.2 * 0.5, 1e-9);  // eq. 79
	EXPECT_NEAR(c(1, 1), 0.01 * 0.5 + 0.5 * 0.2 * 0.5, 1e-9);  // eq. 78
	EXPECT_NEAR(c(2, 2), 0.5 * 0.2, 1e-9);  // eq. 80
	o.model = "fixed";  // independent of the increment
	EXPECT_NEAR(odometryIncrementCovariance(o, TPoseVec(3, 0, 1))(2, 2), 0.5 * 5 * M_PI / 180, 1e-9);
	o.model = "proportional";
	const auto p = odometryIncrementCovariance(o, TPoseVec(1.0, 0, 0));
	EXPECT_NEAR(std::sqrt(p(0, 0)), o.xy_std_per_m + o.min_xy_std_m, 1e-9);
}

TEST(AdaptiveMeasurementNoise, OverconfidentMatcherIsTrustedLessAndNeverMore)
{
	CAdaptiveMeasurementNoise a;
	const Eigen::Matrix3d R = diag(0.01, 0.01);
	for (int k = 0; k < 30; ++k) a.observeNis(30.0);  // 10x the expected NIS of 3
	EXPECT_GT(a.scale(), 5.0);
	EXPECT_NEAR(a.effectiveCovariance(R, false)(0, 0), R(0, 0) * a.scale(), 1e-15);
	EXPECT_NEAR(a.effectiveCovariance(R, true)(0, 0), R(0, 0) * a.scale() * 10.0, 1e-12);
	for (int k = 0; k < 200; ++k) a.observeNis(0.1);
	EXPECT_DOUBLE_EQ(a.scale(), 1.0);  // min_scale
}

TEST(PoseUKF, AbsoluteNisIsTheUpdatesNisWithoutTheUpdate)
{
	// Hand-derived: P = diag(0.01, 0.01, 0.01), R = the same, S = 0.02 I;
	// z = (0.1, 0, 2 pi - 0.1) is 0.1 off in x and, wrapped, -0.1 in theta:
	// NIS = (0.01 + 0.01) / 0.02 = 1.
	CPoseUKF ukf;
	ukf.reset(TPoseVec(0, 0, 0), Eigen::Matrix3d::Identity() * 0.01);
	const TPoseVec z(0.1, 0, 2 * M_PI - 0.1);
	const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 0.01;
	const double nis = ukf.absoluteNis(z, R);
	EXPECT_NEAR(nis, 1.0, 1e-9);
	EXPECT_NEAR(ukf.pose().norm(), 0.0, 1e-12);  // the state is untouched
	EXPECT_NEAR(ukf.updateAbsolute(z, R, 50).nis, nis, 1e-6);  // the update's own figure
}

TEST(PoseUKF, InflatedPredictionPassesTheGateAndKeepsTheCloneCorrelation)
{
	// Hand-derived: P = 0.01 I and R = 0.01 I give S = 0.02 I; z = 0.3 off in
	// x: NIS = 0.09 / 0.02 = 4.5. Inflated 4x, S = 0.05 I and NIS = 1.8. The
	// clone's cross-covariance (P_cc, equal to P after cloning) grows by 2x.
	CPoseUKF ukf;
	ukf.reset(TPoseVec(0, 0, 0), Eigen::Matrix3d::Identity() * 0.01);
	ukf.cloneCurrentPose();
	const TPoseVec z(0.3, 0, 0);
	const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 0.01;
	EXPECT_NEAR(ukf.absoluteNis(z, R), 4.5, 1e-9);
	EXPECT_FALSE(ukf.updateAbsolute(z, R, 3.0).accepted);
	ukf.inflateCurrentPoseCovariance(4.0);
	EXPECT_NEAR(ukf.covariance()(0, 0), 0.04, 1e-9);  // + the eigenvalue floor
	EXPECT_NEAR(ukf.absoluteNis(z, R), 1.8, 1e-6);
	ukf.inflateCurrentPoseCovariance(0.5);  // never shrinks
	EXPECT_NEAR(ukf.covariance()(0, 0), 0.04, 1e-9);  // + the eigenvalue floor
	const auto r = ukf.updateAbsolute(z, R, 3.0);
	ASSERT_TRUE(r.accepted);
	EXPECT_NEAR(ukf.pose()[0], 0.3 * 0.04 / 0.05, 1e-6);  // Kalman gain 0.8
	// The clone moved with the correlation: P_cc / P_c = 0.02 / 0.04 of the correction.
	EXPECT_NEAR(ukf.clonePose()[0], 0.3 * 0.02 / 0.05, 1e-6);
}

TEST(PoseUKF, HeadingNoiseWiderThanTheCircleIsKeptAtTheUniformCirclesVariance)
{
	// Hand-derived: heading noise within the circle adds exactly (the heading
	// is linear in it); a noise of 245 deg std (a turn rate carried 8 s
	// without odometry) is scaled to leave the predicted heading variance at
	// the uniform circle's, pi^2 / 3 (std 104 deg). Unscaled, its sigma
	// points (1.5 std from the mean with n = 9, alpha = 0.5) wrapped round
	// the circle and the predicted heading std came out as 5 deg.
	const double pStd = 1.0 * M_PI / 180, smallStd = 30.0 * M_PI / 180, hugeStd = 245.0 * M_PI / 180;
	CPoseUKF ukf;
	ukf.reset(TPoseVec::Zero(), diag(0.05, pStd));
	ukf.cloneCurrentPose();
	ukf.predict(TPoseVec::Zero(), diag(0.1, smallStd));
	EXPECT_NEAR(ukf.covariance()(2, 2), pStd * pStd + smallStd * smallStd, 1e-9);
	ukf.reset(TPoseVec::Zero(), diag(0.05, pStd));
	ukf.cloneCurrentPose();
	ukf.predict(TPoseVec::Zero(), diag(0.1, hugeStd));
	EXPECT_NEAR(ukf.covariance()(2, 2), CPoseUKF::kUniformCircleHeadingVariance, 1e-9);
	EXPECT_NEAR(ukf.pose()[2], 0.0, 1e-9);
	// a match 160 deg round now passes the gate: NIS = 2.79^2 / (3.29 + R)
	const double off = 160.0 * M_PI / 180;
	const Eigen::Matrix3d R = diag(0.05, 2.0 * M_PI / 180);
	const double nis = ukf.absoluteNis(TPoseVec(0, 0, off), R);
	EXPECT_NEAR(nis, off * off / (CPoseUKF::kUniformCircleHeadingVariance + R(2, 2)), 0.05);
	EXPECT_TRUE(ukf.updateAbsolute(TPoseVec(0, 0, off), R, 50).accepted);
}
