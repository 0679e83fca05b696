/* hslam: the wide search after an odometry gap (see CGapSearch.h). */
#include <hslam/slam/CGapSearch.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace hslam::slam
{
namespace
{
graph::TPointCloud2D toCloud(const mrpt::maps::CSimplePointsMap& map)
{
	const auto& xs = map.getPointsBufferRef_x();
	const auto& ys = map.getPointsBufferRef_y();
	graph::TPointCloud2D out;
	out.reserve(xs.size());
	for (size_t i = 0; i < xs.size(); ++i) out.emplace_back(xs[i], ys[i]);
	return out;
}
}  // namespace

CGapSearch::CGapSearch(const TGapSearchOptions& options)
	: m_options(options),
	  m_afterGap(matcherOptions(ESearchKind::after_gap)),
	  m_afterPoorMatch(matcherOptions(ESearchKind::after_poor_match))
{
}

graph::TCorrelativeMatcherOptions CGapSearch::matcherOptions(ESearchKind kind) const
{
	graph::TCorrelativeMatcherOptions o;
	o.resolution_m = m_options.resolution_m;
	o.kernel_sigma_m = m_options.kernel_sigma_m;
	o.min_score = m_options.min_score;
	// both scans lie in their scanner's frame: one range rule
	o.max_query_range_m = kind == ESearchKind::after_poor_match ? m_options.slip_max_range_m : m_options.max_range_m;
	return o;
}

graph::TSearchWindow CGapSearch::cappedWindow(const Eigen::Matrix3d& motionCov) const
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(motionCov.topLeftCorner<2, 2>());
	const double xyStd_m = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
	const double yawStd_rad = std::sqrt(std::max(0.0, motionCov(2, 2)));
	graph::TSearchWindow w;
	w.xy_m = std::min(m_options.max_window_xy_m, m_options.window_sigmas * xyStd_m);
	w.yaw_rad = std::min(m_options.max_window_yaw_rad, m_options.window_sigmas * yawStd_rad);
	// intel without odometry, t = 947 s: 8 s of a turn rate carried put the
	// prediction 140 deg off, outside a 60 deg window
	if (m_options.whole_circle_if_heading_unknown && m_options.window_sigmas * yawStd_rad >= M_PI) w.yaw_rad = M_PI;
	return w;
}

std::optional<graph::TSearchWindow> CGapSearch::windowFor(const Eigen::Matrix3d& motionCov) const
{
	if (!m_options.enabled) return std::nullopt;
	const graph::TSearchWindow w = cappedWindow(motionCov);
	if (w.xy_m <= m_options.min_window_xy_m && w.yaw_rad <= m_options.min_window_yaw_rad) return std::nullopt;
	return w;
}

std::optional<graph::TSearchWindow> CGapSearch::slipWindowFor(const Eigen::Matrix3d& motionCov) const
{
	if (!m_options.enabled || !m_options.after_poor_match) return std::nullopt;
	graph::TSearchWindow w = cappedWindow(motionCov);
	w.yaw_rad = std::max(w.yaw_rad, m_options.slip_min_yaw_rad);
	return w;
}

std::optional<mrpt::poses::CPose2D> CGapSearch::search(const mrpt::maps::CSimplePointsMap& previous,
														const mrpt::maps::CSimplePointsMap& scan,
														const mrpt::poses::CPose2D& guess,
														const graph::TSearchWindow& window, ESearchKind kind)
{
	graph::CCorrelativeScanMatcher& matcher = kind == ESearchKind::after_poor_match ? m_afterPoorMatch : m_afterGap;
	const graph::TPointCloud2D reference = matcher.filteredQuery(toCloud(previous));
	if (reference.size() < 10) return std::nullopt;
	matcher.setReference(reference);
	const graph::TCorrelativeMatch m =
		matcher.match(toCloud(scan), guess.asTPose(), window, nullptr, -1, graph::EMatchOutput::pose_only);
	if (m.query_points < 10 || !m.found) return std::nullopt;
	return mrpt::poses::CPose2D(m.pose);
}

}  // namespace hslam::slam
