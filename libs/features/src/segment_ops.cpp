/* hslam: steps shared by the line extractors (see segment_ops.h). */
#include <hslam/features/segment_ops.h>

#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hslam::features
{
namespace
{
using mrpt::math::TPoint2D;

double distance(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

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

/** Prefix sums of the point moments: the TLS direction and RMS of any index
 * range in O(1) (the merge loop evaluates many overlapping ranges). */
class CRangeMoments
{
   public:
	struct TFit
	{
		bool valid = false;
		double alpha_rad = 0;  //!< normal direction (modulo pi)
		double rms_m = 0;
	};

	explicit CRangeMoments(const TScanPoints& points)
	{
		const size_t n = points.size();
		for (const auto& p : points.xy) m_origin.x += p.x / static_cast<double>(n), m_origin.y += p.y / static_cast<double>(n);
		m_sums.assign(n + 1, {});
		for (size_t i = 0; i < n; ++i)
		{
			const double x = points.xy[i].x - m_origin.x, y = points.xy[i].y - m_origin.y;
			const auto& s = m_sums[i];
			m_sums[i + 1] = {s[0] + x, s[1] + y, s[2] + x * x, s[3] + y * y, s[4] + x * y};
		}
	}

	TFit fit(const TIndexRange& r) const
	{
		TFit f;
		const double n = static_cast<double>(r.size());
		if (r.size() < 2) return f;
		std::array<double, 5> d;
		for (size_t k = 0; k < 5; ++k) d[k] = m_sums[r.end][k] - m_sums[r.begin][k];
		const double mx = d[0] / n, my = d[1] / n;
		const double sxx = d[2] - n * mx * mx, syy = d[3] - n * my * my, sxy = d[4] - n * mx * my;
		if (sxx + syy <= 1e-12) return f;
		f.valid = true;
		f.alpha_rad = 0.5 * std::atan2(2 * sxy, sxx - syy) + M_PI / 2;
		const double smallest = 0.5 * ((sxx + syy) - std::hypot(sxx - syy, 2 * sxy));  // residual sum of squares
		f.rms_m = std::sqrt(std::max(0.0, smallest) / n);
		return f;
	}

   private:
	TPoint2D m_origin{0, 0};
	std::vector<std::array<double, 5>> m_sums;  //!< x, y, xx, yy, xy of the first i points
};

bool canMerge(const TScanPoints& points, const CRangeMoments& moments, const TIndexRange& a, const TIndexRange& b,
			  const TMergeRule& rule, double& mergedRms)
{
	if (a.end != b.begin) return false;
	if (rule.max_gap_m > 0 && distance(points.xy[a.end - 1], points.xy[b.begin]) > rule.max_gap_m) return false;
	if (rule.max_gap_ratio > 0 && gapCriterion(points, a, b) > rule.max_gap_ratio) return false;
	const auto fa = moments.fit(a), fb = moments.fit(b);
	// noise of one wall: the larger RMS of the two (a few points can look collinear by chance)
	const double sigma = std::max(fa.rms_m, fb.rms_m);
	if (fa.valid && fb.valid && directionStdError_rad(points, a, sigma) < rule.max_angle_rad / 3 &&
		directionStdError_rad(points, b, sigma) < rule.max_angle_rad / 3 &&
		lineAngleDifference_rad(fa.alpha_rad, fb.alpha_rad) > rule.max_angle_rad)
		return false;
	const TIndexRange both{a.begin, b.end};
	const auto merged = moments.fit(both);
	if (!merged.valid) return false;
	if (rule.max_rms_m > 0 && merged.rms_m > rule.max_rms_m) return false;
	if (rule.max_rms_growth > 0)
	{
		const double na = static_cast<double>(a.size()), nb = static_cast<double>(b.size());
		const double pooled = std::sqrt((na * fa.rms_m * fa.rms_m + nb * fb.rms_m * fb.rms_m) / (na + nb));
		if (merged.rms_m > rule.max_rms_growth * pooled + kMergeRmsFloor_m) return false;
	}
	if (rule.max_residual_m > 0 && fitRange(points, both).max_residual_m > rule.max_residual_m) return false;
	mergedRms = merged.rms_m;
	return true;
}
}  // namespace

TLineFit fitRange(const TScanPoints& points, const TIndexRange& range)
{
	return fitLineTotalLeastSquares(points.xy.data() + range.begin, range.size());
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
	s.var_rho_m2 = fit.var_rho_m2;
	s.var_alpha_rad2 = fit.var_alpha_rad2;
	s.cov_rho_alpha_m_rad = fit.cov_rho_alpha_m_rad;
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
		// a point moves only if it is an inlier of the neighbour's fit (not a stray point far from both)
		const double inlierA = std::max(fa.max_residual_m, 0.01), inlierB = std::max(fb.max_residual_m, 0.01);
		if (std::abs(fb.distanceTo(lastA)) < std::abs(fa.distanceTo(lastA)) && std::abs(fb.distanceTo(lastA)) <= inlierB)
		{
			--a.end;  // the last point of a belongs to b's wall
			--b.begin;
		}
		else if (std::abs(fa.distanceTo(firstB)) < std::abs(fb.distanceTo(firstB)) &&
				 std::abs(fa.distanceTo(firstB)) <= inlierA)
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
	// cost[k]: merged RMS of ranges k and k+1, +inf if they may not merge;
	// only the two costs next to a merge change, so each is computed once per change
	const double never = std::numeric_limits<double>::infinity();
	const CRangeMoments moments(points);
	auto cost = [&](size_t k) {
		double rms = 0;
		return canMerge(points, moments, ranges[k], ranges[k + 1], rule, rms) ? rms : never;
	};
	std::vector<double> costs;
	for (size_t k = 0; k + 1 < ranges.size(); ++k) costs.push_back(cost(k));
	for (;;)
	{
		const auto best = std::min_element(costs.begin(), costs.end());
		if (best == costs.end() || *best == never) return;
		const size_t k = static_cast<size_t>(best - costs.begin());
		ranges[k].end = ranges[k + 1].end;
		ranges.erase(ranges.begin() + static_cast<std::ptrdiff_t>(k) + 1);
		costs.erase(costs.begin() + static_cast<std::ptrdiff_t>(k));
		if (k + 1 < ranges.size()) costs[k] = cost(k);
		if (k > 0) costs[k - 1] = cost(k - 1);
	}
}

TLineSegmentList segmentsFromRanges(const TScanPoints& points, const std::vector<TIndexRange>& ranges,
									size_t min_points, double min_length_m, double max_rms_m)
{
	TLineSegmentList out;
	for (const TIndexRange& r : ranges)
	{
		if (r.size() < std::max<size_t>(2, min_points) || !fitRange(points, r).valid) continue;
		TLineSegment s = makeSegment(points, r);
		if (s.length_m() >= min_length_m && (max_rms_m <= 0 || s.fit_rms_m <= max_rms_m)) out.push_back(s);
	}
	return out;
}

namespace
{
/** `beam` lies just outside `line`, next to its end beam `endBeam`. */
bool beamOccludes(const common::TRangeData& scan, const TLineSegment& line, long beam, size_t endBeam)
{
	if (beam < 0 || static_cast<size_t>(beam) >= scan.beamCount()) return true;  // scan border
	const auto i = static_cast<size_t>(beam);
	if (!scan.valid[i]) return true;  // unknown what lies there
	const double nx = std::cos(line.alpha_rad), ny = std::sin(line.alpha_rad);
	const double along = nx * scan.cos_bearing[i] + ny * scan.sin_bearing[i];
	if (std::abs(along) < 1e-9) return true;
	const double t = (line.rho_m - nx * scan.sensor_pose.x() - ny * scan.sensor_pose.y()) / along;  // range at which the beam meets the line
	if (t <= 0) return true;
	const double tol = kOcclusionTolerance_m + 3 * line.fit_rms_m;
	if (scan.range_m[i] >= t - tol) return false;  // sees the line's extension or past it: the wall ends
	// In front of the extension: an occluder, unless the point continues the
	// end point (a concave corner: the next wall starts right there).
	const double endRange = scan.range_m[endBeam];
	const mrpt::math::TPoint2D p = scan.alongBeam(i, scan.range_m[i]), q = scan.alongBeam(endBeam, endRange);
	return std::hypot(p.x - q.x, p.y - q.y) > 2 * endRange * scan.points.beam_step_rad + tol;
}
}  // namespace

void markOccludedEnds(const common::TRangeData& scan, TLineSegmentList& lines)
{
	for (TLineSegment& l : lines)
	{
		l.p0_occluded = beamOccludes(scan, l, static_cast<long>(l.first_beam) - 1, l.first_beam);
		l.p1_occluded = beamOccludes(scan, l, static_cast<long>(l.last_beam) + 1, l.last_beam);
	}
}

}  // namespace hslam::features
