/* hslam: running the dynamic object filter over a recording and scoring
 * the legs it reports against annotated legs (leg_dataset.h), at three
 * output levels:
 *   detected  every leg the detector accepts;
 *   dynamic   legs flagged dynamic at their scan (causal: what
 *             beam_is_dynamic and tracks.csv use);
 *   late      legs whose leg or person track is confirmed dynamic at that
 *             scan or later (a smoother's answer: what the late exclusion
 *             of a batch run removes from the map).
 * Used by hslam-bench legs and the real-data tests. */
#pragma once

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <mrpt/math/TPoint2D.h>

#include <memory>
#include <vector>

namespace hslam::benchdata
{
/** Legs reported per scan (robot frame). */
using TLegsPerScan = std::vector<std::vector<dynamic::TLegSegment>>;

struct TLegOutputLevels
{
	TLegsPerScan detected, dynamic, late;
	double seconds = 0;  //!< time spent in dynamic::CDynamicObjectFilter::process
};

/** Runs a fresh filter (with `classifier`, null: the options' detector)
 * over `scans` taken at robot poses `poses` (one per scan). */
TLegOutputLevels runLegFilter(const dynamic::CDynamicObjectFilter::TOptions& options,
							  const std::shared_ptr<const dynamic::CLegClassifier>& classifier,
							  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
							  const std::vector<mrpt::poses::CPose2D>& poses);

struct TLegScore
{
	size_t scans = 0, annotated = 0, matched = 0;
	size_t arc_unmatched = 0;  //!< reported legs in the annotated arc matching no annotation
	size_t outside_arc = 0;  //!< reported legs outside it (not scored)
	size_t annotated_in_range = 0, matched_in_range = 0;  //!< annotations nearer than maxRange_m
};

/** Matches reported legs to the annotations of each scan, one to one,
 * nearest first within matchRadius_m. */
TLegScore scoreAgainstAnnotations(const TLegsPerScan& reported,
								  const std::vector<std::vector<mrpt::math::TPoint2D>>& annotations,
								  double matchRadius_m, double maxRange_m);

}  // namespace hslam::benchdata
