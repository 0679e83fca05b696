/* CGraphBackend: a verified closure enters the graph only when a second one
 * agrees with it (see CLoopClosureDetector.h, after the verification steps).
 *
 * Why: in a corridor whose walls are straight but for a door niche, a scan
 * whose range reaches past the submap's end scores best where most of its
 * points fall on the submap, not where its niche meets the submap's niche;
 * such a closure passes every single-scan test (simulated corridor: two
 * accepted, 1.1 m and 2.2 m wrong along the axis, score 0.65-0.77, ICP
 * goodness 0.72-0.81, unique in their windows). True closures come in runs:
 * the next keyframes see the same place and ask for the same correction;
 * these two found no partner. */
#include <hslam/graph/CGraphBackend.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace hslam::graph
{
namespace
{
const char* const kAwaiting = "awaiting confirmation";

bool verifiedAndLive(const TLoopClosure& c) { return c.accepted || c.reason == kAwaiting; }
}  // namespace

bool closuresAgree(const TLoopClosure& a, const TLoopClosure& b, const CPoseGraph& graph, double xy_m, double yaw_rad)
{
	const auto& n = graph.nodes();
	// the world-frame correction a asks for, applied to b's query node
	const auto matchedA = composePose(n[a.anchor_node].pose, a.relative);
	const auto correctionA = composePose(matchedA, relativePose(n[a.query_node].pose, {0, 0, 0}));
	const auto predictedB = composePose(correctionA, n[b.query_node].pose);
	const auto d = relativePose(composePose(n[b.anchor_node].pose, b.relative), predictedB);
	return std::hypot(d.x, d.y) <= xy_m && std::abs(mrpt::math::wrapToPi(d.phi)) <= yaw_rad;
}

std::vector<size_t> CGraphBackend::confirmClosures(std::vector<TLoopClosure>& tested)
{
	const auto& o = m_detector.options();
	std::vector<size_t> released;
	if (o.confirm_within_keyframes <= 0) return released;
	auto agree = [&](const TLoopClosure& a, const TLoopClosure& b) {
		return closuresAgree(a, b, m_graph, o.confirm_xy_m, o.confirm_yaw_rad);
	};
	std::vector<bool> confirmed(tested.size(), false);
	for (size_t i = 0; i < tested.size(); ++i)
	{
		if (!tested[i].accepted) continue;
		for (size_t j = 0; j < tested.size(); ++j)
			if (j != i && tested[j].accepted && tested[j].submap != tested[i].submap && agree(tested[i], tested[j]))
				confirmed[i] = true;
		for (const size_t k : m_recentVerified)
		{
			if (!verifiedAndLive(m_closures[k]) || !agree(tested[i], m_closures[k])) continue;
			confirmed[i] = true;
			if (!m_closures[k].accepted && std::find(released.begin(), released.end(), k) == released.end())
				released.push_back(k);
		}
	}
	for (size_t i = 0; i < tested.size(); ++i)
		if (tested[i].accepted && !confirmed[i]) tested[i].accepted = false, tested[i].reason = kAwaiting;
	return released;
}

void CGraphBackend::rememberVerified(size_t node, size_t firstNew)
{
	for (size_t k = firstNew; k < m_closures.size(); ++k)
		if (verifiedAndLive(m_closures[k])) m_recentVerified.push_back(k);
	const size_t window = static_cast<size_t>(std::max(0, m_detector.options().confirm_within_keyframes));
	auto expired = [&](size_t k) { return m_closures[k].query_node + window < node; };
	for (const size_t k : m_recentVerified)
		if (expired(k) && m_closures[k].reason == kAwaiting) m_closures[k].reason = "not confirmed";
	m_recentVerified.erase(std::remove_if(m_recentVerified.begin(), m_recentVerified.end(), expired),
						   m_recentVerified.end());
}
}  // namespace hslam::graph
