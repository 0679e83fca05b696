/* hslam: ATE after closed-form SE(2) alignment. */
#include <hslam/eval/absolute_trajectory_error.h>
#include <hslam/eval/se2_alignment.h>

#include <vector>

namespace hslam::eval
{
namespace
{
std::vector<mrpt::math::TPoint2D> positions(const common::TTrajectory2D& trajectory)
{
	std::vector<mrpt::math::TPoint2D> out;
	out.reserve(trajectory.size());
	for (const auto& p : trajectory) out.emplace_back(p.pose.x, p.pose.y);
	return out;
}

}  // namespace

TAbsoluteTrajectoryError computeAbsoluteTrajectoryError(const common::TTrajectory2D& reference,
														const common::TTrajectory2D& estimate)
{
	const auto refPoints = positions(reference), estPoints = positions(estimate);
	const mrpt::poses::CPose2D alignment = alignPointsSE2(estPoints, refPoints);

	std::vector<double> errors_m;
	errors_m.reserve(estPoints.size());
	for (size_t k = 0; k < estPoints.size(); ++k)
		errors_m.push_back((alignment + estPoints[k] - refPoints[k]).norm());

	TAbsoluteTrajectoryError ate;
	ate.alignment = alignment.asTPose();
	ate.position_m = computeErrorStats(errors_m);
	return ate;
}

}  // namespace hslam::eval
