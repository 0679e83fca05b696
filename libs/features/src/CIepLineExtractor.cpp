/* hslam: iterative end point fit with collinear merge (thesis 4.4.3 i; see
 * CIepLineExtractor.h). */
#include <hslam/common/options_io.h>
#include <hslam/features/CIepLineExtractor.h>
#include <hslam/features/scan_points.h>
#include <hslam/features/segment_ops.h>

namespace hslam::features
{
TLineSegmentList CIepLineExtractor::extract(const common::TRangeData& scan) const
{
	const TScanPoints& points = scan.points;
	std::vector<TIndexRange> ranges;
	for (const TIndexRange& run : consecutiveBeamRuns(points))
		for (const TIndexRange& piece : splitAtPointGaps(points, run, m_options.max_point_gap_m))
		{
			const auto parts = splitByChord(points, piece, m_options.split_distance_m);
			ranges.insert(ranges.end(), parts.begin(), parts.end());
		}
	refineBoundaries(points, ranges);
	TMergeRule rule;
	rule.max_angle_rad = m_options.merge_angle_rad;
	rule.max_residual_m = m_options.split_distance_m;
	rule.max_gap_m = m_options.max_point_gap_m;
	mergeCollinearNeighbours(points, ranges, rule);
	refineBoundaries(points, ranges);
	TLineSegmentList lines =
		segmentsFromRanges(points, ranges, static_cast<size_t>(m_options.min_points), m_options.min_length_m);
	markOccludedEnds(scan, lines);
	return lines;
}

void CIepLineExtractor::saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const
{
	hslam::common::saveOptions(m_options, out, section);
}

}  // namespace hslam::features
