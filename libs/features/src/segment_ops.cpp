/* hslam: steps shared by the line extractors (see segment_ops.h). */
#include <hslam/features/segment_ops.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::features
{
namespace
{
using mrpt::math::TPoint2D;

double distance(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

std::vector<TPoint2D> gather(const TScanPoints& points, const TIndexRange& range)
{
	return {points.xy.begin() + static_cast<std::ptrdiff_t>(range.begin),
			points.xy.begin() + static_cast<std::ptrdiff_t>(range.end)};
}

/** Distance of p from the infinite line through a and b (|p - a| if a == b). */
double distanceToChord(const TPoint2D& p, const TPoint2D& a, const TPoint2D& b)
{
	const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
	if (len <= 0) return distance(p, a);
	return std::abs((p.x - a.x) * dy - (p.y - a.y) * dx) / len;
}

/** Standard error of the direction of a TLS fit of range r (rad) for point
 * noise sigma_m: sigma sqrt(12 / n) / extent. */
double directionStdError_rad(const TScanPoints& points, const TIndexRange& r, double sigma_m)
{
	const double extent = distance(points.xy[r.begin], points.xy[r.end - 1]);
	if (extent <= 0 || r.size() < 3) return std::numeric_limits<double>::infinity();
	return std::max(sigma_m, 1e-3) * std::sqrt(12.0 / static_cast<double>(r.size())) / extent;
}

bool canMerge(const TScanPoints& points, const TIndexRange& a, const TIndexRange& b, const TMergeRule& rule,
			  double& mergedRms)
{
	if (a.end != b.begin) return false;
	if (rule.max_gap_m > 0 && distance(points.xy[a.end - 1], points.xy[b.begin]) > rule.max_gap_m) return false;
	if (rule.max_gap_ratio > 0 && gapCriterion(points, a, b) > rule.max_gap_ratio) return false;
	const TLineFit fa = fitRange(points, a), fb = fitRange(points, b);
	// noise of one wall: the larger RMS of the two (a few points can look collinear by chance)
	const double sigma = std::max(fa.rms_m, fb.rms_m);
	if (fa.valid && fb.valid && directionStdError_rad(points, a, sigma) < rule.max_angle_rad / 3 &&
		directionStdError_rad(points, b, sigma) < rule.max_angle_rad / 3 &&
		lineAngleDifference_rad(fa.alpha_rad, fb.alpha_rad) > rule.max_angle_rad)
		return false;
	const TLineFit merged = fitRange(points, {a.begin, b.end});
	if (!merged.valid) return false;
	if (rule.max_residual_m > 0 && merged.max_residual_m > rule.max_residual_m) return false;
	if (rule.max_rms_growth > 0)
	{
		const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
		const double pooled = std::sqrt((na * fa.rms_m * fa.rms_m + nb * fb.rms_m * fb.rms_m) / (na + nb));
		if (merged.rms_m > rule.max_rms_growth * pooled + kMergeRmsFloor_m) return false;
	}
	mergedRms = merged.rms_m;
	return true;
}
}  // namespace

TLineFit fitRange(const TScanPoints& points, const TIndexRange& range)
{
	return fitLineTotalLeastSquares(gather(points, range));
}

TLineSegment makeSegment(const TScanPoints& points, const std::vector<size_t>& indices)
{
	std::vector<TPoint2D> xy;
	xy.reserve(indices.size());
	for (size_t i : indices) xy.push_back(points.xy[i]);
	const TLineFit fit = fitLineTotalLeastSquares(xy);
	TLineSegment s;
	s.rho_m = fit.rho_m;
	s.alpha_rad = fit.alpha_rad;
	s.p0 = fit.project(xy.front());
	s.p1 = fit.project(xy.back());
	s.first_beam = points.beam[indices.front()];
	s.last_beam = points.beam[indices.back()];
	s.point_count = indices.size();
	s.fit_rms_m = fit.rms_m;
	return s;
}

TLineSegment makeSegment(const TScanPoints& points, const TIndexRange& range)
{
	std::vector<size_t> indices(range.size());
	for (size_t i = 0; i < indices.size(); ++i) indices[i] = range.begin + i;
	return makeSegment(points, indices);
}

std::vector<TIndexRange> splitByChord(const TScanPoints& points, const TIndexRange& range, double max_distance_m)
{
	std::vector<TIndexRange> done, todo{range};
	while (!todo.empty())
	{
		const TIndexRange r = todo.back();
		todo.pop_back();
		double worst = 0;
		size_t worstIndex = r.begin;
		for (size_t i = r.begin + 1; i + 1 < r.end; ++i)
		{
			const double d = distanceToChord(points.xy[i], points.xy[r.begin], points.xy[r.end - 1]);
			if (d > worst)
			{
				worst = d;
				worstIndex = i;
			}
		}
		if (worst <= max_distance_m)
		{
			done.push_back(r);
			continue;
		}
		todo.push_back({worstIndex, r.end});  // processed first: keeps `done` in order after the sort below
		todo.push_back({r.begin, worstIndex});
	}
	std::sort(done.begin(), done.end(), [](const TIndexRange& x, const TIndexRange& y) { return x.begin < y.begin; });
	return done;
}

std::vector<TIndexRange> splitAtPointGaps(const TScanPoints& points, const TIndexRange& range, double max_gap_m)
{
	std::vector<TIndexRange> out;
	if (range.size() == 0) return out;
	out.push_back({range.begin, range.begin + 1});
	for (size_t i = range.begin + 1; i < range.end; ++i)
	{
		if (distance(points.xy[i - 1], points.xy[i]) > max_gap_m) out.push_back({i, i});
		out.back().end = i + 1;
	}
	return out;
}

void refineBoundaries(const TScanPoints& points, std::vector<TIndexRange>& ranges)
{
	for (size_t k = 0; k + 1 < ranges.size(); ++k)
	{
		TIndexRange &a = ranges[k], &b = ranges[k + 1];
		if (a.end != b.begin || points.beam[b.begin] != points.beam[a.end - 1] + 1) continue;
		if (a.size() < 3 || b.size() < 3) continue;
		const TLineFit fa = fitRange(points, {a.begin, a.end - 1}), fb = fitRange(points, {b.begin + 1, b.end});
		if (!fa.valid || !fb.valid) continue;
		const TPoint2D &lastA = points.xy[a.end - 1], &firstB = points.xy[b.begin];
		if (std::abs(fb.distanceTo(lastA)) < std::abs(fa.distanceTo(lastA)))
		{
			--a.end;  // the last point of a belongs to b's wall
			--b.begin;
		}
		else if (std::abs(fa.distanceTo(firstB)) < std::abs(fb.distanceTo(firstB)))
		{
			++a.end;
			++b.begin;
		}
	}
}

double gapCriterion(const TScanPoints& points, const TIndexRange& first, const TIndexRange& second)
{
	const double gap = distance(points.xy[first.end - 1], points.xy[second.begin]);
	const double a = distance(points.xy[first.begin], points.xy[first.end - 1]);
	const double b = distance(points.xy[second.begin], points.xy[second.end - 1]);
	const size_t steps = first.size() + second.size() - 2;  // point spacings inside the two pieces
	if (a + b <= 0 || steps == 0) return std::numeric_limits<double>::infinity();
	const double aa = std::max(0.0, gap - (a + b) / static_cast<double>(steps));
	return (aa + a + b) / (a + b);
}

void mergeCollinearNeighbours(const TScanPoints& points, std::vector<TIndexRange>& ranges, const TMergeRule& rule)
{
	for (;;)
	{
		double best = std::numeric_limits<double>::infinity();
		size_t bestK = ranges.size();
		for (size_t k = 0; k + 1 < ranges.size(); ++k)
		{
			double rms = 0;
			if (canMerge(points, ranges[k], ranges[k + 1], rule, rms) && rms < best)
			{
				best = rms;
				bestK = k;
			}
		}
		if (bestK == ranges.size()) return;
		ranges[bestK].end = ranges[bestK + 1].end;
		ranges.erase(ranges.begin() + static_cast<std::ptrdiff_t>(bestK) + 1);
	}
}

TLineSegmentList segmentsFromRanges(const TScanPoints& points, const std::vector<TIndexRange>& ranges,
									size_t min_points, double min_length_m)
{
	TLineSegmentList out;
	for (const TIndexRange& r : ranges)
	{
		if (r.size() < std::max<size_t>(2, min_points) || !fitRange(points, r).valid) continue;
		TLineSegment s = makeSegment(points, r);
		if (s.length_m() >= min_length_m) out.push_back(s);
	}
	return out;
}

}  // namespace hslam::features
