/* hslam: scoring extracted lines against ground truth (see line_scoring.h). */
#include <hslam/benchdata/line_scoring.h>
#include <hslam/features/line_fit.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace hslam::benchdata
{
namespace
{
double dist(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

double TLineScore::f1() const
{
	const double p = precision(), r = recall();
	return p + r > 0 ? 2 * p * r / (p + r) : 0.0;
}

bool segmentMatches(const features::TLineSegment& s, const TVisibleWall& truth, const TLineMatchTolerance& tol, double& overlap)
{
	overlap = 0;
	const double L = truth.length_m();
	if (L <= 0) return false;
	const double ux = (truth.p1.x - truth.p0.x) / L, uy = (truth.p1.y - truth.p0.y) / L;
	// direction difference of undirected lines, via their normals
	const double truthNormal = std::atan2(uy, ux) + M_PI / 2;
	if (features::lineAngleDifference_rad(s.alpha_rad, truthNormal) > tol.max_angle_rad) return false;
	auto offLine = [&](const mrpt::math::TPoint2D& p) {
		return std::abs((p.x - truth.p0.x) * uy - (p.y - truth.p0.y) * ux);
	};
	if (offLine(s.p0) > tol.max_distance_m || offLine(s.p1) > tol.max_distance_m) return false;
	const double u0 = (s.p0.x - truth.p0.x) * ux + (s.p0.y - truth.p0.y) * uy;
	const double u1 = (s.p1.x - truth.p0.x) * ux + (s.p1.y - truth.p0.y) * uy;
	const double covered = std::min(std::max(u0, u1), L) - std::max(std::min(u0, u1), 0.0);
	overlap = std::max(0.0, covered) / L;
	return overlap >= tol.min_overlap;
}

TLineScore scoreLines(const std::vector<TVisibleWall>& truth, const features::TLineSegmentList& extracted,
					  const TLineMatchTolerance& tol)
{
	TLineScore score;
	score.truth = truth.size();
	score.extracted = extracted.size();
	score.match_of_truth.assign(truth.size(), -1);
	std::vector<std::tuple<double, size_t, size_t>> candidates;  // overlap, truth, extracted
	for (size_t t = 0; t < truth.size(); ++t)
		for (size_t e = 0; e < extracted.size(); ++e)
		{
			double overlap = 0;
			if (segmentMatches(extracted[e], truth[t], tol, overlap)) candidates.emplace_back(overlap, t, e);
		}
	std::sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) { return std::get<0>(a) > std::get<0>(b); });
	std::vector<bool> used(extracted.size(), false);
	for (const auto& [overlap, t, e] : candidates)
	{
		if (score.match_of_truth[t] >= 0 || used[e]) continue;
		score.match_of_truth[t] = static_cast<int>(e);
		used[e] = true;
		++score.found;
		const double e0 = dist(extracted[e].p0, truth[t].p0), e1 = dist(extracted[e].p1, truth[t].p1);
		score.sum_endpoint_error_m += 0.5 * (e0 + e1);
		score.max_endpoint_error_m = std::max({score.max_endpoint_error_m, e0, e1});
	}
	score.false_positives = extracted.size() - score.found;
	return score;
}

}  // namespace hslam::benchdata
