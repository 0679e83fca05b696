/* Test helpers: a keyframe trajectory through waypoints with exact ground
 * truth, and a drifting front-end (noise + heading bias + scale error) whose
 * relative poses and declared covariance feed CGraphBackend. */
#pragma once

#include <hslam/graph/CGraphBackend.h>
#include <mrpt/math/wrap2pi.h>

#include "sim_scans.h"

namespace hslam::graph::testing
{
/** Keyframe poses every step_m along the polyline, turning in place at the
 * corners in steps of at most maxTurn_rad. */
inline std::vector<mrpt::math::TPose2D> keyframePath(const std::vector<mrpt::math::TPoint2D>& waypoints,
													 double step_m = 0.5, double maxTurn_rad = 0.35)
{
	std::vector<mrpt::math::TPose2D> out;
	double yaw = std::atan2(waypoints[1].y - waypoints[0].y, waypoints[1].x - waypoints[0].x);
	out.push_back({waypoints[0].x, waypoints[0].y, yaw});
	for (size_t w = 1; w < waypoints.size(); ++w)
	{
		const auto a = waypoints[w - 1], b = waypoints[w];
		const double target = std::atan2(b.y - a.y, b.x - a.x);
		const double turn = mrpt::math::wrapToPi(target - yaw);
		const int turns = static_cast<int>(std::ceil(std::abs(turn) / maxTurn_rad));
		for (int i = 1; i <= turns; ++i) out.push_back({a.x, a.y, yaw + turn * i / turns});
		yaw = target;
		const double len = std::hypot(b.x - a.x, b.y - a.y);
		const int steps = std::max(1, static_cast<int>(std::round(len / step_m)));
		for (int i = 1; i <= steps; ++i) out.push_back({a.x + (b.x - a.x) * i / steps, a.y + (b.y - a.y) * i / steps, yaw});
	}
	return out;
}

struct TFrontEndErrors
{
	double noise_xy_m = 0.01, noise_yaw_rad = mrpt::DEG2RAD(0.2);
	double yaw_bias_rad_per_keyframe = mrpt::DEG2RAD(0.1);
	double scale_error = 0.01;
	double declared_xy_std_m = 0.03, declared_yaw_std_rad = mrpt::DEG2RAD(0.5);
};

struct TRunResult
{
	std::vector<mrpt::math::TPose2D> truth, frontend, optimized;
	std::vector<TLoopClosure> closures;
	TBackendTiming timing;
};

/** Root-mean-square position error of `poses` against `truth`. */
inline double ate_m(const std::vector<mrpt::math::TPose2D>& poses, const std::vector<mrpt::math::TPose2D>& truth)
{
	double s = 0;
	for (size_t i = 0; i < poses.size(); ++i)
		s += std::pow(poses[i].x - truth[i].x, 2) + std::pow(poses[i].y - truth[i].y, 2);
	return std::sqrt(s / poses.size());
}

/** Runs the back-end over the path in `world` with a drifting front-end. */
inline TRunResult runBackend(const sim::CWorld& world, const std::vector<mrpt::math::TPose2D>& truth,
							 const TFrontEndErrors& err, CGraphBackend& backend, uint64_t seed = 1)
{
	std::mt19937_64 rng(seed);
	std::normal_distribution<double> n01(0.0, 1.0);
	TRunResult r;
	r.truth = truth;
	for (size_t k = 0; k < truth.size(); ++k)
	{
		TKeyframe kf;
		kf.id = static_cast<int64_t>(k);
		if (k == 0) kf.pose = truth[0];
		else
		{
			const auto rel = relativePose(truth[k - 1], truth[k]);
			const mrpt::math::TPose2D measured{rel.x * (1 + err.scale_error) + err.noise_xy_m * n01(rng),
											   rel.y + err.noise_xy_m * n01(rng),
											   rel.phi + err.yaw_bias_rad_per_keyframe + err.noise_yaw_rad * n01(rng)};
			kf.pose = composePose(r.frontend.back(), measured);
			kf.relative_covariance = Eigen::Vector3d(err.declared_xy_std_m * err.declared_xy_std_m,
													 err.declared_xy_std_m * err.declared_xy_std_m,
													 err.declared_yaw_std_rad * err.declared_yaw_std_rad)
										 .asDiagonal();
		}
		kf.points = scanPoints(world, truth[k], rng);
		r.frontend.push_back(kf.pose);
		backend.addKeyframe(kf);
	}
	backend.flushPendingClosures();  // the end of the run
	r.optimized = backend.optimizedPoses();
	r.closures = backend.closures();
	r.timing = backend.timing();
	return r;
}

/** Error of an accepted closure's relative pose against ground truth. */
inline void closureError(const TLoopClosure& c, const std::vector<mrpt::math::TPose2D>& truth, double& xy_m,
						 double& yaw_rad)
{
	const auto trueRel = relativePose(truth[c.anchor_node], truth[c.query_node]);
	const auto e = relativePose(trueRel, c.relative);
	xy_m = std::hypot(e.x, e.y);
	yaw_rad = std::abs(mrpt::math::wrapToPi(e.phi));
}

}  // namespace hslam::graph::testing
