/* hslam: scoring extracted lines against ground-truth visible walls (the
 * "lines found" and "false positives" of thesis table 3, made precise).
 *
 * An extracted segment matches a true wall part if
 *   - their directions differ by at most max_angle (3 deg),
 *   - both of its endpoints lie within max_distance_m (5 cm) of the true
 *     wall's line, and
 *   - its projection onto the true part covers at least min_overlap (50 %)
 *     of the true part's length.
 * Matching is one-to-one, largest overlap first. A true part with a match is
 * "found"; an extracted segment without one is a false positive (so a wall
 * split in two halves counts one found and one false positive, as the thesis
 * counted its split wall in figure 105). Endpoint error of a match: the mean
 * distance of its two endpoints to the true part's endpoints (both in beam
 * order). */
#pragma once

#include <hslam/benchdata/synthetic_scan.h>
#include <hslam/features/line_segment.h>

#include <vector>

namespace hslam::benchdata
{
struct TLineMatchTolerance
{
	double max_distance_m = 0.05;
	double max_angle_rad = 3.0 * M_PI / 180;
	double min_overlap = 0.5;
};

struct TLineScore
{
	size_t truth = 0, extracted = 0;
	size_t found = 0;  //!< true parts matched
	size_t false_positives = 0;  //!< extracted segments not matched
	double sum_endpoint_error_m = 0;  //!< over matches (mean = sum / found)
	double max_endpoint_error_m = 0;  //!< largest single endpoint distance over matches
	std::vector<int> match_of_truth;  //!< index into the extracted list, or -1

	double recall() const { return truth ? static_cast<double>(found) / truth : 1.0; }
	double precision() const { return extracted ? static_cast<double>(found) / extracted : 1.0; }
	double f1() const;
	double meanEndpointError_m() const { return found ? sum_endpoint_error_m / found : 0.0; }
};

/** Does `s` match `truth` (see above); overlap fraction returned in `overlap`. */
bool segmentMatches(const features::TLineSegment& s, const TVisibleWall& truth, const TLineMatchTolerance& tol, double& overlap);

TLineScore scoreLines(const std::vector<TVisibleWall>& truth, const features::TLineSegmentList& extracted,
					  const TLineMatchTolerance& tol = {});

}  // namespace hslam::benchdata
