#include <hslam/graph/CLoopClosureDetector.h>
#include <hslam/graph/adaptive_voxel_filter.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <thread>

#include "loop_closure_candidate.h"

namespace hslam::graph
{
namespace
{
/** Each keyframe's origin and points in the anchor frame. */
std::vector<TSubmapView> submapViews(const std::vector<std::pair<size_t, TPointCloud2D>>& keyframes,
									 const CPoseGraph& graph, size_t anchor)
{
	std::vector<TSubmapView> views;
	for (const auto& [node, points] : keyframes)
	{
		const auto rel = mrpt::poses::CPose2D(relativePose(graph.nodes()[anchor].pose, graph.nodes()[node].pose));
		TSubmapView v;
		v.origin = {static_cast<float>(rel.x()), static_cast<float>(rel.y())};
		v.points.reserve(points.size());
		for (const auto& p : points)
		{
			double x, y;
			rel.composePoint(p.x, p.y, x, y);
			v.points.push_back({static_cast<float>(x), static_cast<float>(y)});
		}
		views.push_back(std::move(v));
	}
	return views;
}

/** The views' points, one per cell of `cell_m`. */
TPointCloud2D thinnedPoints(const std::vector<TSubmapView>& views, double cell_m)
{
	TPointCloud2D all;
	for (const auto& v : views) all.insert(all.end(), v.points.begin(), v.points.end());
	return voxelFilter(all, cell_m);
}
}  // namespace

double closureInformationGain(const Eigen::Matrix3d& relative, double closureXyStd_m, double closureYawStd_rad)
{
	const Eigen::Vector3d closureVar(closureXyStd_m * closureXyStd_m, closureXyStd_m * closureXyStd_m,
									 closureYawStd_rad * closureYawStd_rad);
	const Eigen::Matrix3d sum = 0.5 * (relative + relative.transpose()) + Eigen::Matrix3d(closureVar.asDiagonal());
	return 0.5 * std::log(sum.determinant() / closureVar.prod());
}

double largestXyVariance(const Eigen::Matrix3d& covariance)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> xy(covariance.topLeftCorner<2, 2>());
	return std::max(0.0, xy.eigenvalues().maxCoeff());
}

namespace
{
/** search_threads, or with 0 one per hardware thread but no more than a
 * keyframe has candidates (more would never get work). */
size_t searchThreads(const TLoopClosureOptions& o)
{
	if (o.search_threads > 0) return static_cast<size_t>(o.search_threads);
	const size_t hardware = std::max(1u, std::thread::hardware_concurrency());
	return std::min(hardware, static_cast<size_t>(std::max(1, o.max_candidates)));
}
}  // namespace

CLoopClosureDetector::CLoopClosureDetector(const TOptions& options)
	: m_options(options), m_pool(std::make_unique<common::CTaskPool>(searchThreads(options)))
{
}
CLoopClosureDetector::~CLoopClosureDetector() = default;

void CLoopClosureDetector::addKeyframe(size_t node, const TPointCloud2D& points, const CPoseGraph& graph)
{
	m_queryNode = node;
	m_queryPoints = points;
	m_query = CCorrelativeScanMatcher::prepareQuery(points, m_options.matcher);
	m_pending.emplace_back(node, points);
	if (static_cast<int>(m_pending.size()) >= m_options.submap_keyframes) closeSubmap(graph);
}

void CLoopClosureDetector::closeSubmap(const CPoseGraph& graph)
{
	TSubmap s;
	s.first_node = m_pending.front().first;
	s.last_node = m_pending.back().first;
	s.anchor_node = m_pending[m_pending.size() / 2].first;
	s.views = submapViews(m_pending, graph, s.anchor_node);
	s.points = thinnedPoints(s.views, m_options.matcher.resolution_m);
	m_submaps.push_back(std::move(s));
	m_pending.clear();
}

CLoopClosureDetector::TSubmapField* CLoopClosureDetector::cachedField(size_t submap, bool& needsBuild)
{
	needsBuild = false;
	for (auto it = m_fieldCache.begin(); it != m_fieldCache.end(); ++it)
		if (it->first == submap)
		{
			m_fieldCache.splice(m_fieldCache.begin(), m_fieldCache, it);
			return m_fieldCache.front().second.get();
		}
	std::unique_ptr<TSubmapField> field;
	if (!m_fieldCache.empty() && static_cast<int>(m_fieldCache.size()) >= m_options.max_cached_fields)
	{  // the least recently used field is rebuilt in its own buffers
		field = std::move(m_fieldCache.back().second);
		m_fieldCache.pop_back();
		field->points.clear();
	}
	else
		field = std::make_unique<TSubmapField>(TSubmapField{CCorrelativeScanMatcher(m_options.matcher), {}, {}});
	m_fieldCache.emplace_front(submap, std::move(field));
	while (static_cast<int>(m_fieldCache.size()) > m_options.max_cached_fields) m_fieldCache.pop_back();
	needsBuild = true;
	return m_fieldCache.front().second.get();
}

void CLoopClosureDetector::buildField(TSubmapField& field, size_t submap) const
{
	const auto& points = m_submaps[submap].points;
	field.matcher.setReference(points);
	field.free.build(field.matcher.grid(), m_submaps[submap].views);
	field.points.reserve(points.size());
	for (const auto& p : points) field.points.insertPointFast(p.x, p.y, 0);
}

std::vector<CLoopClosureDetector::TCandidate> CLoopClosureDetector::candidates(
	size_t node, const CPoseGraph& graph, const TRelativeCovariance& relativeCovariance)
{
	const auto& query = graph.nodes()[node].pose;
	std::vector<TCandidate> out;
	for (size_t s = 0; s < m_submaps.size(); ++s)
	{
		const auto& sm = m_submaps[s];
		if (sm.last_node + static_cast<size_t>(m_options.min_separation_keyframes) > node) continue;
		const auto& anchor = graph.nodes()[sm.anchor_node].pose;
		const auto relative = relativeCovariance(sm.anchor_node);
		if (!relative) continue;
		TCandidate c;
		c.submap = s;
		c.relativeCovariance = *relative;
		c.xy_std_m = std::sqrt(largestXyVariance(c.relativeCovariance));
		c.yaw_std_rad = std::sqrt(std::max(0.0, c.relativeCovariance(2, 2)));
		c.window.xy_m =
			std::clamp(m_options.window_sigmas * c.xy_std_m, m_options.min_window_xy_m, m_options.max_window_xy_m);
		c.window.yaw_rad = std::clamp(m_options.window_sigmas * c.yaw_std_rad, m_options.min_window_yaw_rad,
									  m_options.max_window_yaw_rad);
		c.distance_m = std::hypot(query.x - anchor.x, query.y - anchor.y);
		if (c.distance_m > m_options.overlap_distance_m + c.window.xy_m) continue;
		c.information_gain_nats = closureInformationGain(c.relativeCovariance, m_options.closure_xy_std_m,
														 m_options.closure_yaw_std_rad);
		const auto track = m_tracks.find(s);
		if (track != m_tracks.end() && track->second.in_a_row < m_options.max_tracked_in_a_row) c.track = track->second;
		if (c.information_gain_nats < m_options.min_information_gain_nats)
		{
			++m_skippedLittleInformation;
			continue;
		}
		out.push_back(c);
	}
	std::sort(out.begin(), out.end(), [](const TCandidate& a, const TCandidate& b) { return a.distance_m < b.distance_m; });
	if (static_cast<int>(out.size()) > m_options.max_candidates) out.resize(static_cast<size_t>(m_options.max_candidates));
	return out;
}

std::vector<CLoopClosureDetector::TCandidate> CLoopClosureDetector::searched(
	size_t node, const CPoseGraph& graph, const TRelativeCovariance& relativeCovariance)
{
	std::vector<TCandidate> out;
	for (const auto& c : candidates(node, graph, relativeCovariance))
	{
		// Seen from a keyframe 0.5 m away, a submap that matched nowhere in
		// its window rarely matches now; its slot is not handed to a farther
		// candidate (that would cost the same and overlap less).
		if (within(m_lowScoreAt, c.submap, node, m_options.retest_low_score_after_keyframes))
			++m_skippedRecentLowScore;
		// The widest window means the prior no longer bounds the search:
		// approaching an old place after a long loop, keyframe after keyframe
		// finds nothing there until the overlap suffices, each search costing
		// 5-20x a narrow one (Cartographer likewise runs its searches over a
		// whole submap less often than its local ones). A search that found
		// the place but could not verify it (ambiguous, ICP) is repeated at
		// once: that is how such a place gets closed a keyframe later.
		else if (isWide(c.window.xy_m) &&
				 within(m_wideLowScoreAt, c.submap, node, m_options.retest_wide_after_keyframes))
			++m_skippedRecentWide;
		else
			out.push_back(c);
	}
	return out;
}

bool CLoopClosureDetector::within(const std::map<size_t, size_t>& lastAt, size_t submap, size_t node, int keyframes)
{
	const auto last = lastAt.find(submap);
	return last != lastAt.end() && node < last->second + static_cast<size_t>(keyframes);
}

bool CLoopClosureDetector::isWide(double window_xy_m) const { return window_xy_m >= m_options.max_window_xy_m; }

std::vector<TLoopClosure> CLoopClosureDetector::verifyAll(const std::vector<TCandidate>& cands, size_t node,
														  const CPoseGraph& graph)
{
	std::vector<TLoopClosure> out(cands.size());
	const size_t batch = static_cast<size_t>(std::max(1, m_options.max_cached_fields));
	for (size_t first = 0; first < cands.size(); first += batch)
	{
		const size_t count = std::min(batch, cands.size() - first);
		// the cache is only touched here: the batch's fields are its most recent
		// ones; those not cached are built side by side (each in its own buffers)
		std::vector<TSubmapField*> fields;
		std::vector<size_t> toBuild;
		for (size_t k = 0; k < count; ++k)
		{
			bool needsBuild = false;
			fields.push_back(cachedField(cands[first + k].submap, needsBuild));
			if (needsBuild) toBuild.push_back(k);
		}
		m_pool->run(toBuild.size(),
					[&](size_t i) { buildField(*fields[toBuild[i]], cands[first + toBuild[i]].submap); });
		m_pool->run(count, [&](size_t k) { out[first + k] = verify(cands[first + k], *fields[k], node, graph); });
	}
	return out;
}

void CLoopClosureDetector::keepTracks(size_t node, const std::vector<TLoopClosure>& closures)
{
	std::map<size_t, TClosureTrack> tracks;
	if (m_options.max_tracked_in_a_row > 0)  // else nothing is ever tracked
		for (const auto& c : closures)
			if (c.accepted && c.query_node == node) tracks[c.submap] = TClosureTrack{node, c.relative, c.tracked_in_a_row};
	m_tracks = std::move(tracks);
}

std::vector<TLoopClosure> CLoopClosureDetector::detect(size_t node, const CPoseGraph& graph,
													   const TRelativeCovariance& relativeCovariance)
{
	if (node != m_queryNode || node % static_cast<size_t>(m_options.detect_every_n_keyframes) != 0) return {};
	// Candidates are verified side by side; what follows is the order a
	// one-by-one search would have seen them in, so the result is the same.
	std::vector<TLoopClosure> out = verifyAll(searched(node, graph, relativeCovariance), node, graph);
	int accepted = 0;
	for (size_t k = 0; k < out.size(); ++k)
	{
		if (out[k].reason == "low score")
		{
			m_lowScoreAt[out[k].submap] = node;
			if (isWide(out[k].window_xy_m)) m_wideLowScoreAt[out[k].submap] = node;
		}
		accepted += out[k].accepted ? 1 : 0;
		if (m_options.max_closures_per_keyframe > 0 && accepted >= m_options.max_closures_per_keyframe)
		{
			out.resize(k + 1);
			break;
		}
	}
	return out;
}

}  // namespace hslam::graph
