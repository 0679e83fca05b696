/* hslam: the valid returns of a 2D laser scan as points in the robot frame,
 * the common input of every line extractor: the `points` part of the scan's
 * range-data record (common/range_data.h, built once per scan, with the one
 * validity rule common::isValidReturn). Invalid beams are simply absent, so no
 * extractor can ever build a line or a corner from them; `beam` keeps each
 * point's original index so that gaps left by invalid beams stay visible. */
#pragma once

#include <hslam/common/range_data.h>

#include <cstddef>
#include <vector>

namespace hslam::features
{
using common::TScanPoints;

/** Half-open index range [begin, end) into a TScanPoints. */
struct TIndexRange
{
	size_t begin = 0, end = 0;
	size_t size() const { return end - begin; }
};

/** Maximal runs of points whose beams are consecutive (split at every invalid beam). */
std::vector<TIndexRange> consecutiveBeamRuns(const TScanPoints& points);

}  // namespace hslam::features
