/* hslam: the wide search after an odometry gap (see CGapSearch.h). */
#include <hslam/slam/CGapSearch.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace hslam::slam
{
namespace
{
/** The points of `map` within range_m of its origin (the scanner). */
graph::TPointCloud2D withinRange(const mrpt::maps::CSimplePointsMap& map, double range_m)
{
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	graph::TPointCloud2D out;
	out.reserve(xs.size());
	const float r2 = static_cast<float>(range_m * range_m);
	for (size_t i = 0; i < xs.size(); ++i)
		if (xs[i] * xs[i] + ys[i] * ys[i] <= r2) out.emplace_back(xs[i], ys[i]);
	return out;
}
}  // namespace

std::optional<graph::TSearchWindow> CGapSearch::windowFor(const Eigen::Matrix3d& motionCov) const
{
	if (!m_options.enabled) return std::nullopt;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(motionCov.topLeftCorner<2, 2>());
	const double xyStd_m = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
	const double yawStd_rad = std::sqrt(std::max(0.0, motionCov(2, 2)));
	graph::TSearchWindow w;
	w.xy_m = std::min(m_options.max_window_xy_m, m_options.window_sigmas * xyStd_m);
	w.yaw_rad = std::min(m_options.max_window_yaw_rad, m_options.window_sigmas * yawStd_rad);
	if (w.xy_m <= m_options.min_window_xy_m && w.yaw_rad <= m_options.min_window_yaw_rad) return std::nullopt;
	return w;
}

std::optional<mrpt::poses::CPose2D> CGapSearch::search(const mrpt::maps::CSimplePointsMap& previous,
														const mrpt::maps::CSimplePointsMap& scan,
														const mrpt::poses::CPose2D& guess,
														const graph::TSearchWindow& window) const
{
	const graph::TPointCloud2D reference = withinRange(previous, m_options.max_range_m);
	const graph::TPointCloud2D query = withinRange(scan, m_options.max_range_m);
	if (reference.size() < 10 || query.size() < 10) return std::nullopt;
	graph::TCorrelativeMatcherOptions o;
	o.resolution_m = m_options.resolution_m;
	o.kernel_sigma_m = m_options.kernel_sigma_m;
	o.min_score = m_options.min_score;
	graph::CCorrelativeScanMatcher matcher(o);
	matcher.setReference(reference);
	const graph::TCorrelativeMatch m =
		matcher.match(query, guess.asTPose(), window, nullptr, -1, graph::EMatchOutput::pose_only);
	if (!m.found) return std::nullopt;
	return mrpt::poses::CPose2D(m.pose);
}

}  // namespace hslam::slam
