/* hslam: line segmentation by the second derivative of the log range
 * (thesis 4.4.2 i-ii; see CDerivativeLineExtractor.h). */
#include <hslam/common/options_io.h>
#include <hslam/features/CDerivativeLineExtractor.h>
#include <hslam/features/segment_ops.h>

#include <algorithm>
#include <cmath>

namespace hslam::features
{
namespace
{
/** Second derivative of ln(range) w.r.t. beam index (step k, divided by k),
 * zero where the stencil leaves the run; `has` marks computed values. */
void logRangeSecondDerivative(const TScanPoints& points, const std::vector<TIndexRange>& runs, size_t k,
							  std::vector<double>& d2, std::vector<bool>& has)
{
	d2.assign(points.size(), 0.0);
	has.assign(points.size(), false);
	for (const TIndexRange& run : runs)
	{
		if (run.size() < 2 * k + 1) continue;
		for (size_t i = run.begin + k; i + k < run.end; ++i)
		{
			d2[i] = (std::log(points.range_m[i + k]) - 2 * std::log(points.range_m[i]) +
					 std::log(points.range_m[i - k])) /
					static_cast<double>(k);
			has[i] = true;
		}
	}
}

/** One thresholding pass (figure 82): normalise by the largest remaining
 * peak, keep |d2| above the threshold, mark a piece start at every zero
 * crossing inside a cluster of kept values, or at the largest peak of a
 * cluster without one; the clusters (widened by k) are then excluded. */
void peakPass(const std::vector<double>& d2, const std::vector<TIndexRange>& runs, size_t k, double relThreshold,
			  double floor, std::vector<bool>& excluded, std::vector<bool>& startsPiece)
{
	double peak = 0;
	for (size_t i = 0; i < d2.size(); ++i)
		if (!excluded[i]) peak = std::max(peak, std::abs(d2[i]));
	if (peak <= 0) return;
	const double threshold = std::max(relThreshold * peak, floor);
	auto kept = [&](size_t i) { return !excluded[i] && std::abs(d2[i]) > threshold; };
	for (const TIndexRange& run : runs)
	{
		for (size_t c0 = run.begin; c0 < run.end; ++c0)
		{
			if (!kept(c0)) continue;
			size_t c1 = c0;
			while (c1 + 1 < run.end && kept(c1 + 1)) ++c1;
			bool zeroCrossing = false;
			size_t largest = c0;
			for (size_t j = c0; j <= c1; ++j)
			{
				if (j < c1 && (d2[j] > 0) != (d2[j + 1] > 0))
				{
					startsPiece[j + 1] = true;  // a jump lies between beams j and j+1
					zeroCrossing = true;
				}
				if (std::abs(d2[j]) > std::abs(d2[largest])) largest = j;
			}
			if (!zeroCrossing) startsPiece[largest] = true;  // corner (mono peak)
			const size_t from = c0 >= run.begin + k ? c0 - k : run.begin;
			const size_t to = std::min(run.end - 1, c1 + k);
			for (size_t j = from; j <= to; ++j) excluded[j] = true;
			c0 = c1;
		}
	}
}
}  // namespace

std::vector<TIndexRange> CDerivativeLineExtractor::segmentByDerivative(const TScanPoints& points) const
{
	// runs of consecutive valid beams, also cut where neighbouring points are
	// farther apart than max_point_gap_m (no derivative across such a gap)
	std::vector<TIndexRange> runs;
	for (const TIndexRange& run : consecutiveBeamRuns(points))
	{
		const auto parts = splitAtPointGaps(points, run, m_options.max_point_gap_m);
		runs.insert(runs.end(), parts.begin(), parts.end());
	}
	const double step_rad = points.beam_step_rad > 0 ? points.beam_step_rad : M_PI / 180;
	const size_t k = static_cast<size_t>(std::max(1.0, std::round(m_options.derivative_step_rad / step_rad)));
	const double floor = m_options.min_peak * step_rad / (M_PI / 180);  // min_peak is given for 1 deg beams
	std::vector<double> d2;
	std::vector<bool> has;
	logRangeSecondDerivative(points, runs, k, d2, has);

	std::vector<bool> startsPiece(points.size(), false), excluded(points.size());
	for (size_t i = 0; i < points.size(); ++i) excluded[i] = !has[i];
	for (const TIndexRange& run : runs) startsPiece[run.begin] = true;
	// Two passes, each normalised by its own largest peak (see the header:
	// one depth jump must not hide the corners).
	for (int pass = 0; pass < 2; ++pass)
		peakPass(d2, runs, k, m_options.peak_threshold, floor, excluded, startsPiece);

	std::vector<TIndexRange> pieces;
	for (size_t i = 0; i < points.size(); ++i)
	{
		if (startsPiece[i]) pieces.push_back({i, i});
		pieces.back().end = i + 1;
	}
	return pieces;
}

TLineSegmentList CDerivativeLineExtractor::extract(const common::TRangeData& scan) const
{
	const TScanPoints& points = scan.points;
	std::vector<TIndexRange> ranges;
	for (const TIndexRange& piece : segmentByDerivative(points))
	{
		const auto parts = splitByChord(points, piece, m_options.split_distance_m);
		ranges.insert(ranges.end(), parts.begin(), parts.end());
	}
	refineBoundaries(points, ranges);
	TMergeRule rule;
	rule.max_angle_rad = m_options.merge_angle_rad;
	rule.max_rms_growth = m_options.merge_rms_growth;
	rule.max_rms_m = m_options.max_fit_rms_m;
	rule.max_gap_ratio = m_options.gap_ratio;
	rule.max_gap_m = m_options.max_point_gap_m;
	mergeCollinearNeighbours(points, ranges, rule);
	refineBoundaries(points, ranges);
	TLineSegmentList lines =
		segmentsFromRanges(points, ranges, static_cast<size_t>(m_options.min_points), m_options.min_length_m,
						   m_options.max_fit_rms_m);
	markOccludedEnds(scan, lines);
	return lines;
}

void CDerivativeLineExtractor::saveOptions(mrpt::config::CConfigFileBase& out, const std::string& section) const
{
	hslam::common::saveOptions(m_options, out, section);
}

}  // namespace hslam::features
