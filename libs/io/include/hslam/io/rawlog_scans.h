/* hslam: whole-file reading of a rawlog (either format) for tools and
 * benchmarks that need it all in memory; streaming readers use CRawlogReader. */
#pragma once

#include <hslam/io/CRawlogReader.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace hslam::io
{
/** Every 2D range scan of a rawlog, in file order (observations and the
 * observations of sensory frames alike). Throws what CRawlogReader throws. */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> readRangeScans(const std::string& rawlogPath);

/** Every entry of a rawlog, in file order. Throws what CRawlogReader throws. */
std::vector<TRawlogEntry> readRawlogEntries(const std::string& rawlogPath);

}  // namespace hslam::io
