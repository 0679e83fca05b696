/* hslam: timestamp association of estimate and reference poses. */
#include <hslam/eval/trajectory_association.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hslam::eval
{
using common::TTimedPose2D;
using common::TTrajectory2D;

namespace
{
struct TCandidate
{
	double dt_s;  //!< |t_estimate - t_reference|
	size_t estimateIndex, referenceIndex;
};

TTrajectory2D sortedByTime(TTrajectory2D trajectory)
{
	std::stable_sort(trajectory.begin(), trajectory.end(),
					 [](const TTimedPose2D& a, const TTimedPose2D& b) { return a.t_s < b.t_s; });
	return trajectory;
}

/** All (estimate, reference) pairs with |dt| <= max_dt_s, closest first.
 * Both trajectories must be sorted by time. */
std::vector<TCandidate> candidatePairs(const TTrajectory2D& reference, const TTrajectory2D& estimate,
									   double max_dt_s)
{
	std::vector<TCandidate> candidates;
	const auto earlierThan = [](const TTimedPose2D& p, double t_s) { return p.t_s < t_s; };
	for (size_t e = 0; e < estimate.size(); ++e)
	{
		const double t_s = estimate[e].t_s;
		auto it = std::lower_bound(reference.begin(), reference.end(), t_s - max_dt_s, earlierThan);
		for (; it != reference.end() && it->t_s <= t_s + max_dt_s; ++it)
		{
			const double dt_s = std::abs(it->t_s - t_s);
			if (dt_s <= max_dt_s)
				candidates.push_back({dt_s, e, static_cast<size_t>(it - reference.begin())});
		}
	}
	// stable: equal |dt| keeps the earlier estimate / earlier reference first
	std::stable_sort(candidates.begin(), candidates.end(),
					 [](const TCandidate& a, const TCandidate& b) { return a.dt_s < b.dt_s; });
	return candidates;
}

/** Greedy one-to-one selection; returns (estimate, reference) index pairs
 * sorted by estimate index. */
std::vector<std::pair<size_t, size_t>> selectOneToOne(const std::vector<TCandidate>& candidates,
													   size_t numReference, size_t numEstimate)
{
	std::vector<bool> referenceUsed(numReference, false), estimateUsed(numEstimate, false);
	std::vector<std::pair<size_t, size_t>> pairs;
	for (const auto& c : candidates)
	{
		if (referenceUsed[c.referenceIndex] || estimateUsed[c.estimateIndex]) continue;
		referenceUsed[c.referenceIndex] = estimateUsed[c.estimateIndex] = true;
		pairs.emplace_back(c.estimateIndex, c.referenceIndex);
	}
	std::sort(pairs.begin(), pairs.end());
	return pairs;
}

}  // namespace

TTimeRange timeRange(const TTrajectory2D& trajectory)
{
	TTimeRange range;
	if (trajectory.empty()) return range;
	const auto [first, last] = std::minmax_element(
		trajectory.begin(), trajectory.end(),
		[](const TTimedPose2D& a, const TTimedPose2D& b) { return a.t_s < b.t_s; });
	range.empty = false;
	range.first_s = first->t_s;
	range.last_s = last->t_s;
	return range;
}

TAssociation associateByTimestamp(const TTrajectory2D& reference, const TTrajectory2D& estimate,
								  double max_dt_s)
{
	if (!std::isfinite(max_dt_s) || max_dt_s < 0)
		throw std::invalid_argument("max_dt must be a finite number >= 0 s, got " + std::to_string(max_dt_s));
	const TTrajectory2D ref = sortedByTime(reference), est = sortedByTime(estimate);
	const auto pairs = selectOneToOne(candidatePairs(ref, est, max_dt_s), ref.size(), est.size());

	TAssociation out;
	for (const auto& [e, r] : pairs)
	{
		out.estimate.push_back(est[e]);
		out.reference.push_back(ref[r]);
	}
	out.unmatched_reference = ref.size() - pairs.size();
	out.unmatched_estimate = est.size() - pairs.size();
	return out;
}

}  // namespace hslam::eval
