#include <hslam/fusion/se2.h>

#include <cmath>

namespace hslam::fusion
{
double wrapToPi(double a)
{
	a = std::remainder(a, 2.0 * M_PI);  // [-pi, pi]
	return a <= -M_PI ? a + 2.0 * M_PI : a;
}

TPoseVec compose(const TPoseVec& a, const TPoseVec& b)
{
	const double c = std::cos(a[2]), s = std::sin(a[2]);
	return {a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], wrapToPi(a[2] + b[2])};
}

TPoseVec inverseCompose(const TPoseVec& a, const TPoseVec& b)
{
	const double c = std::cos(b[2]), s = std::sin(b[2]);
	const double dx = a[0] - b[0], dy = a[1] - b[1];
	return {c * dx + s * dy, -s * dx + c * dy, wrapToPi(a[2] - b[2])};
}

TPoseVec weightedPoseMean(const Eigen::Matrix3Xd& poses, const Eigen::VectorXd& weights)
{
	TPoseVec mean = TPoseVec::Zero();
	double sinSum = 0, cosSum = 0;
	for (Eigen::Index i = 0; i < poses.cols(); ++i)
	{
		mean[0] += weights[i] * poses(0, i);
		mean[1] += weights[i] * poses(1, i);
		sinSum += weights[i] * std::sin(poses(2, i));
		cosSum += weights[i] * std::cos(poses(2, i));
	}
	mean[2] = std::atan2(sinSum, cosSum);
	return mean;
}

}  // namespace hslam::fusion
