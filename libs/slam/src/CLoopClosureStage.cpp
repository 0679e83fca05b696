#include <hslam/slam/CLoopClosureStage.h>

#include <Eigen/Eigenvalues>
#include <cmath>

namespace hslam::slam
{
namespace
{
/** Symmetric part of m with its eigenvalues clamped to [0, max]: a filter's
 * covariance may hold a huge variance along a direction matching could not
 * observe (the ICP degeneracy cap, 100 m std), which says "unknown", not a
 * relative uncertainty between keyframes, and would make the edge's
 * information matrix numerically singular. */
Eigen::Matrix3d positivePart(const Eigen::Matrix3d& m, double maxVariance)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (m + m.transpose()));
	const Eigen::Vector3d values = eig.eigenvalues().cwiseMax(0.0).cwiseMin(maxVariance);
	return eig.eigenvectors() * values.asDiagonal() * eig.eigenvectors().transpose();
}
}  // namespace

CLoopClosureStage::CLoopClosureStage(const TLoopClosureStageOptions& options,
									 const graph::TGraphBackendOptions& backendOptions,
									 const maps::CTiledGridGeometry& tiles)
	: m_options(options), m_backendOptions(backendOptions), m_tiles(tiles), m_backend(backendOptions, options.detector)
{
	if (!options.background_thread) return;
	m_worker = std::make_unique<common::CSerialWorker<graph::TKeyframe>>([this](graph::TKeyframe& kf) {
		const graph::TKeyframeResult r = m_backend.addKeyframe(kf);
		m_backgroundTimings.push_back({r.time_ms, r.optimized ? r.optimization.time_ms : -1.0});
	});
}

void CLoopClosureStage::wait() const
{
	if (m_worker) m_worker->wait();
}

double CLoopClosureStage::flush()
{
	wait();  // the background thread is idle from here until the next process()
	const auto report = m_backend.flushPendingClosures();
	return report ? report->time_ms : -1.0;
}

const graph::CGraphBackend& CLoopClosureStage::backend() const
{
	wait();
	return m_backend;
}

const std::vector<TBackendCallTiming>& CLoopClosureStage::backgroundTimings() const
{
	wait();
	return m_backgroundTimings;
}

bool CLoopClosureStage::isKeyframe(const mrpt::math::TPose2D& pose) const
{
	if (m_keyframeOnline.empty()) return true;
	const auto rel = graph::relativePose(m_keyframeOnline.back(), pose);
	return std::hypot(rel.x, rel.y) >= m_options.keyframe_every_m ||
		   std::abs(rel.phi) >= m_options.keyframe_every_rad;
}

Eigen::Matrix3d CLoopClosureStage::relativeCovariance(const TPoseEstimate& estimate) const
{
	// Growth of the front-end's world-frame covariance, in the previous keyframe's frame.
	const auto& prev = m_keyframeOnline.back();
	Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
	R(0, 0) = R(1, 1) = std::cos(prev.phi);
	R(1, 0) = std::sin(prev.phi), R(0, 1) = -R(1, 0);
	const double maxVariance = 1.0;  // (1 m)^2 / (1 rad)^2: as weak as an edge across an odometry gap
	const Eigen::Matrix3d frontEnd = m_options.edge_covariance == "posterior"
										 ? estimate.covariance
										 : Eigen::Matrix3d(estimate.covariance - m_lastKeyframeCovariance);
	Eigen::Matrix3d cov = positivePart(R.transpose() * frontEnd * R, maxVariance);
	// Floor in proportion to the motion (see file comment).
	const auto rel = graph::relativePose(prev, estimate.pose.asTPose());
	const double travel_m = std::hypot(rel.x, rel.y);
	const double xyStd_m = m_options.relative_xy_std_per_m * travel_m;
	const double yawStd_rad =
		m_options.relative_yaw_std_rad_per_m * travel_m + m_options.relative_yaw_std_per_rad * std::abs(rel.phi);
	cov(0, 0) = std::max(cov(0, 0), xyStd_m * xyStd_m);
	cov(1, 1) = std::max(cov(1, 1), xyStd_m * xyStd_m);
	cov(2, 2) = std::max(cov(2, 2), yawStd_rad * yawStd_rad);
	return cov;
}

int CLoopClosureStage::tileGroup(const mrpt::math::TPose2D& pose)
{
	const maps::TTileIndex tile = m_tiles.tileOf(m_tiles.cellOf(pose.x, pose.y));
	return m_tileGroups.emplace(tile, static_cast<int>(m_tileGroups.size())).first->second;
}

std::optional<graph::TKeyframeResult> CLoopClosureStage::process(const TPoseEstimate& estimate,
																 const common::TRangeData& scan,
																 const std::vector<bool>* excludedBeams)
{
	const mrpt::math::TPose2D pose = estimate.pose.asTPose();
	const size_t scanIndex = m_scanOnline.size();
	m_scanOnline.push_back(pose);
	m_gapSinceKeyframe |= estimate.motion_prior == "gap" || estimate.motion_prior == "jump";
	if (!isKeyframe(pose))
	{
		m_scanKeyframe.push_back(m_keyframeOnline.size() - 1);
		return std::nullopt;
	}
	graph::TKeyframe kf;
	kf.id = static_cast<int64_t>(scanIndex);  // keyframe id = scan index: closures map back to scans
	kf.pose = pose;
	if (!m_keyframeOnline.empty()) kf.relative_covariance = relativeCovariance(estimate);
	kf.after_gap = m_gapSinceKeyframe;
	kf.group = tileGroup(pose);
	kf.points.reserve(scan.points.size());
	for (size_t i = 0; i < scan.points.size(); ++i)
		if (!excludedBeams || !(*excludedBeams)[scan.points.beam[i]])
			kf.points.emplace_back(static_cast<float>(scan.points.xy[i].x), static_cast<float>(scan.points.xy[i].y));
	m_keyframeOnline.push_back(pose);
	m_lastKeyframeCovariance = estimate.covariance;
	m_gapSinceKeyframe = false;
	m_scanKeyframe.push_back(m_keyframeOnline.size() - 1);
	if (!m_worker) return m_backend.addKeyframe(kf);
	m_worker->push(std::move(kf));
	return std::nullopt;
}

std::vector<mrpt::poses::CPose2D> CLoopClosureStage::correctedScanPoses() const
{
	const auto& nodes = backend().graph().nodes();
	std::vector<mrpt::poses::CPose2D> out;
	out.reserve(m_scanOnline.size());
	for (size_t s = 0; s < m_scanOnline.size(); ++s)
	{
		const size_t k = m_scanKeyframe[s];
		out.emplace_back(graph::composePose(nodes[k].pose, graph::relativePose(m_keyframeOnline[k], m_scanOnline[s])));
	}
	return out;
}

}  // namespace hslam::slam
