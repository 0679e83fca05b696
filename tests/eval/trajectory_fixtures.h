/* hslam tests: small hand-made trajectories shared by the eval tests. */
#pragma once

#include <hslam/common/tum_trajectory.h>

#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstddef>

namespace hslam::eval::fixtures
{
/** n poses along +x, step_m apart, heading 0, at t0_s + k * dt_s. */
inline common::TTrajectory2D straightLine(size_t n, double step_m, double t0_s = 100.0, double dt_s = 0.1)
{
	common::TTrajectory2D out;
	for (size_t k = 0; k < n; ++k) out.push_back({t0_s + dt_s * k, {step_m * k, 0.0, 0.0}});
	return out;
}

/** n poses 0.1 s apart of a robot driving 0.1 m per step along a winding
 * path (left and right turns), starting away from the origin. */
inline common::TTrajectory2D windingPath(size_t n, double t0_s = 100.0)
{
	common::TTrajectory2D out;
	mrpt::poses::CPose2D pose(2.0, 1.0, 0.3);
	for (size_t k = 0; k < n; ++k)
	{
		out.push_back({t0_s + 0.1 * k, pose.asTPose()});
		pose = pose + mrpt::poses::CPose2D(0.1, 0.0, 0.08 * std::sin(0.03 * k));
	}
	return out;
}

/** Every pose replaced by transform (+) pose; timestamps kept. */
inline common::TTrajectory2D transformed(const common::TTrajectory2D& trajectory,
										 const mrpt::poses::CPose2D& transform)
{
	common::TTrajectory2D out = trajectory;
	for (auto& p : out) p.pose = (transform + mrpt::poses::CPose2D(p.pose)).asTPose();
	return out;
}

}  // namespace hslam::eval::fixtures
