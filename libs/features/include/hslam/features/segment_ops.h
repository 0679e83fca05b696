/* hslam: steps shared by the line extractors, working on index ranges of the
 * valid scan points (scan_points.h): fitting a range, splitting it (iterative
 * end point rule, point gaps), moving boundary points to the better line,
 * merging collinear neighbours (thesis 4.4.2 i "dealing with noise" and the
 * merge step of split-and-merge, 4.4.3 i step 7) and turning ranges into
 * TLineSegment. */
#pragma once

#include <hslam/features/line_fit.h>
#include <hslam/features/line_segment.h>
#include <hslam/features/scan_points.h>

#include <vector>

namespace hslam::features
{
TLineFit fitRange(const TScanPoints& points, const TIndexRange& range);

/** Segment from the points with the given indices (in beam order): TLS fit,
 * endpoints = projections of the first and last point. Requires >= 2 points
 * that are not all identical (check with fitLineTotalLeastSquares first). */
TLineSegment makeSegment(const TScanPoints& points, const std::vector<size_t>& indices);
TLineSegment makeSegment(const TScanPoints& points, const TIndexRange& range);

/** Iterative end point fit (thesis 4.4.3 i): while a point lies farther than
 * max_distance_m from the chord joining the first and last point of its
 * range, split the range there (the farthest point starts the second part). */
std::vector<TIndexRange> splitByChord(const TScanPoints& points, const TIndexRange& range, double max_distance_m);

/** Splits where two consecutive points are more than max_gap_m apart. */
std::vector<TIndexRange> splitAtPointGaps(const TScanPoints& points, const TIndexRange& range, double max_gap_m);

/** For neighbouring ranges of consecutive beams: the last point of the first
 * range and the first point of the second move to the neighbour if they lie
 * closer to its fitted line and within that fit's largest residual (at least
 * 1 cm) - corner points end up on the wall they belong to, stray points stay. */
void refineBoundaries(const TScanPoints& points, std::vector<TIndexRange>& ranges);

/** Noise floor of the RMS-growth merge test (m). */
constexpr double kMergeRmsFloor_m = 0.005;

/** When two neighbouring ranges are one line (all tests that are enabled pass). */
struct TMergeRule
{
	/** Direction difference of the two fits; tested only if both directions
	 * are known to better than a third of it (standard error of a TLS
	 * direction ~ sigma sqrt(12 / n) / extent, sigma = the larger fit RMS of
	 * the two pieces): a short or noisy piece has no
	 * reliable direction and is judged by the RMS tests alone. */
	double max_angle_rad = 0;
	double max_residual_m = 0;  //!< largest orthogonal residual of the merged fit; <= 0: off
	/** Merged fit RMS <= max_rms_growth * (pooled RMS of the two fits) + kMergeRmsFloor_m,
	 * i.e. merging must not make the fit much worse than the pieces' own noise; <= 0: off. */
	double max_rms_growth = 0;
	double max_rms_m = 0;  //!< hard limit on the merged fit's RMS (growth can chain); <= 0: off
	double max_gap_ratio = 0;  //!< thesis eq. 56: (aa + a + b) / (a + b) must not exceed this; <= 0: off
	double max_gap_m = 0;  //!< distance between the facing end points; <= 0: off
};

/** Thesis eq. 56, (aa + a + b) / (a + b), for two ranges in beam order: a
 * and b are the extents (first to last point) of the two, aa the gap between
 * the last point of the first and the first point of the second MINUS the
 * mean point spacing inside the two (deviation: taken literally, aa is at
 * least one beam spacing, so two halves of one wall of fewer than ~22
 * points in all would always count as a "real gap"); +inf if a + b = 0. */
double gapCriterion(const TScanPoints& points, const TIndexRange& first, const TIndexRange& second);

/** Merges neighbouring ranges (first.end == second.begin) that pass `rule`,
 * best merged fit first, until no pair passes. */
void mergeCollinearNeighbours(const TScanPoints& points, std::vector<TIndexRange>& ranges, const TMergeRule& rule);

/** Segments of the ranges with at least min_points points, length >=
 * min_length_m and fit RMS <= max_rms_m (<= 0: any), in beam order. */
TLineSegmentList segmentsFromRanges(const TScanPoints& points, const std::vector<TIndexRange>& ranges,
									size_t min_points, double min_length_m, double max_rms_m = 0);

/** Sets p0_occluded / p1_occluded of each line (see line_segment.h) from the
 * beams first_beam - 1 and last_beam + 1 of `scan`: occluded if that beam is
 * invalid or outside the scan, if it does not meet the line ahead, or if its
 * range is shorter than the line's along it by more than
 * tol = kOcclusionTolerance_m + 3 fit_rms AND its point is farther than
 * 2 beam spacings + tol from the segment's end point (a concave corner, where
 * the next wall starts right at the end point, is a real end). */
void markOccludedEnds(const common::TRangeData& scan, TLineSegmentList& lines);

constexpr double kOcclusionTolerance_m = 0.05;

}  // namespace hslam::features
