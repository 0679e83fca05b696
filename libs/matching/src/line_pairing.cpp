#include <hslam/fusion/se2.h>
#include <hslam/matching/line_pairing.h>

#include <algorithm>
#include <cmath>

namespace hslam::matching
{
using features::TLineSegment;
using fusion::wrapToPi;

TLineSegment predictLineInCurrentFrame(const TLineSegment& line, const mrpt::poses::CPose2D& currentInPrevious)
{
	TLineSegment out = line;
	const double c = std::cos(line.alpha_rad), s = std::sin(line.alpha_rad);
	out.rho_m = line.rho_m - (c * currentInPrevious.x() + s * currentInPrevious.y());
	out.alpha_rad = wrapToPi(line.alpha_rad - currentInPrevious.phi());
	if (out.rho_m < 0)
	{  // the robot crossed the infinite line: keep rho >= 0
		out.rho_m = -out.rho_m;
		out.alpha_rad = wrapToPi(out.alpha_rad + M_PI);
	}
	const mrpt::poses::CPose2D inverse = -currentInPrevious;
	out.p0 = inverse + line.p0;
	out.p1 = inverse + line.p1;
	return out;
}

std::vector<TLinePair> pairLines(const features::TLineSegmentList& previous, const features::TLineSegmentList& current,
								 const mrpt::poses::CPose2D& predicted, const TLinePairingOptions& o)
{
	std::vector<TLinePair> candidates;
	for (size_t i = 0; i < previous.size(); ++i)
	{
		if (previous[i].length_m() < o.min_line_length_m) continue;
		const TLineSegment expected = predictLineInCurrentFrame(previous[i], predicted);
		for (size_t j = 0; j < current.size(); ++j)
		{
			const TLineSegment& cur = current[j];
			if (cur.length_m() < o.min_line_length_m) continue;
			const double lengthDiff = std::abs(cur.length_m() / previous[i].length_m() - 1.0);
			const double angleDiff = std::abs(wrapToPi(cur.alpha_rad - expected.alpha_rad));
			const double rhoDiff = std::abs(cur.rho_m - expected.rho_m);
			if (lengthDiff > o.max_length_ratio_diff || angleDiff > o.max_angle_diff_rad || rhoDiff > o.max_rho_diff_m)
				continue;
			// Overlap check: the predicted segment's midpoint must project inside the
			// current segment grown by half its length (walls, not just collinear lines).
			const auto d = cur.p1 - cur.p0;
			const double len2 = d.x * d.x + d.y * d.y;
			const auto m = expected.midpoint() - cur.p0;
			const double u = len2 > 0 ? (m.x * d.x + m.y * d.y) / len2 : 0.5;
			if (u < -0.5 || u > 1.5) continue;
			const double cost = std::pow(angleDiff / o.max_angle_diff_rad, 2) + std::pow(rhoDiff / o.max_rho_diff_m, 2) +
								(o.max_length_ratio_diff > 0 ? std::pow(lengthDiff / o.max_length_ratio_diff, 2) : 0.0);
			candidates.push_back({i, j, cost});
		}
	}
	std::sort(candidates.begin(), candidates.end(), [](const TLinePair& a, const TLinePair& b) { return a.cost < b.cost; });
	std::vector<bool> usedPrev(previous.size()), usedCur(current.size());
	std::vector<TLinePair> pairs;
	for (const auto& c : candidates)
	{
		if (usedPrev[c.previous] || usedCur[c.current]) continue;
		usedPrev[c.previous] = usedCur[c.current] = true;
		pairs.push_back(c);
	}
	return pairs;
}

}  // namespace hslam::matching
