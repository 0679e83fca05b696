/* hslam: RANSAC lines by MRPT, cut into segments (see CRansacLineExtractor.h). */
#include <hslam/common/options_io.h>
#include <hslam/features/CRansacLineExtractor.h>
#include <hslam/features/scan_points.h>
#include <hslam/features/segment_ops.h>

#include "ransac_lines.h"

#include <mrpt/math/CVectorDynamic.h>
#include <mrpt/math/TLine2D.h>

#include <algorithm>
#include <cmath>

namespace hslam::features
{
namespace
{
/** Cuts the (beam-ordered) indices where consecutive points are more than max_gap_m apart. */
std::vector<std::vector<size_t>> cutAtGaps(const TScanPoints& points, const std::vector<size_t>& indices,
										   double max_gap_m)
{
	std::vector<std::vector<size_t>> pieces;
	for (size_t i : indices)
	{
		if (pieces.empty() || std::hypot(points.xy[i].x - points.xy[pieces.back().back()].x,
										 points.xy[i].y - points.xy[pieces.back().back()].y) > max_gap_m)
			pieces.emplace_back();
		pieces.back().push_back(i);
	}
	return pieces;
}
}  // namespace

TLineSegmentList CRansacLineExtractor::extract(const common::TRangeData& scan) const
{
	const TScanPoints& points = scan.points;
	const size_t n = points.size();
	TLineSegmentList out;
	if (n < static_cast<size_t>(std::max(2, m_options.min_inliers))) return out;
	mrpt::math::CVectorDynamic<double> xs(n), ys(n);
	for (size_t i = 0; i < n; ++i)
	{
		xs[i] = points.xy[i].x;
		ys[i] = points.xy[i].y;
	}
	// MRPT's RANSAC logger prints "Finished in N iterations" at LVL_INFO for
	// every line it looks for; silence_mrpt_log lowers its verbosity to errors.
	const auto lines = detail::detectRansacLines(
		xs, ys, m_options.distance_threshold_m, static_cast<size_t>(m_options.min_inliers),
		m_options.silence_mrpt_log ? mrpt::system::LVL_ERROR : mrpt::system::LVL_INFO);

	// each point goes to the nearest detected line within the threshold
	// (MRPT hands points to the first line that claims them, which gives a
	// wall's corner point to the neighbouring wall when that one was found first)
	std::vector<std::vector<size_t>> members(lines.size());
	for (size_t i = 0; i < n; ++i)
	{
		double best = m_options.distance_threshold_m;
		size_t bestLine = lines.size();
		for (size_t k = 0; k < lines.size(); ++k)
		{
			const double d = lines[k].second.distance(points.xy[i]);
			if (d <= best)
			{
				best = d;
				bestLine = k;
			}
		}
		if (bestLine < lines.size()) members[bestLine].push_back(i);
	}
	for (const auto& inliers : members)
	{
		for (const auto& piece : cutAtGaps(points, inliers, m_options.max_point_gap_m))
		{
			if (piece.size() < static_cast<size_t>(std::max(2, m_options.min_points))) continue;
			std::vector<mrpt::math::TPoint2D> xy;
			for (size_t i : piece) xy.push_back(points.xy[i]);
			if (!fitLineTotalLeastSquares(xy).valid) continue;
			TLineSegment s = makeSegment(points, piece);
			if (s.length_m() >= m_options.min_length_m) out.push_back(s);
		}
	}
	std::sort(out.begin(), out.end(),
			  [](const TLineSegment& a, const TLineSegment& b) { return a.first_beam < b.first_beam; });
	markOccludedEnds(scan, out);
	return out;
}

void CRansacLineExtractor::saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const
{
	hslam::common::saveOptions(m_options, out, section);
}

}  // namespace hslam::features
