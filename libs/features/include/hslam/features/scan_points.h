/* hslam: the valid returns of a 2D laser scan as points in the robot frame,
 * the common input of every line extractor.
 *
 * A beam is valid if its validity flag is set, its range is finite, > 0 and
 * below the scanner's maxRange (a return at maxRange is the "no echo" value).
 * Invalid beams are simply absent, so no extractor can ever build a line or a
 * corner from them; `beam` keeps each point's original index so that gaps
 * left by invalid beams stay visible. */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <vector>

namespace hslam::features
{
struct TScanPoints
{
	std::vector<mrpt::math::TPoint2D> xy;  //!< robot frame (m), in beam order
	std::vector<double> range_m;  //!< the measured range of each point
	std::vector<size_t> beam;  //!< index of each point's beam in the scan

	size_t size() const { return xy.size(); }
};

/** Half-open index range [begin, end) into a TScanPoints. */
struct TIndexRange
{
	size_t begin = 0, end = 0;
	size_t size() const { return end - begin; }
};

bool isValidBeam(const mrpt::obs::CObservation2DRangeScan& scan, size_t i);

/** The valid points of `scan` (sensorPose applied). */
TScanPoints validScanPoints(const mrpt::obs::CObservation2DRangeScan& scan);

/** Maximal runs of points whose beams are consecutive (split at every invalid beam). */
std::vector<TIndexRange> consecutiveBeamRuns(const TScanPoints& points);

}  // namespace hslam::features
