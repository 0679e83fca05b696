/* hslam features (internal): sequential RANSAC line detection on MRPT's
 * RANSAC_Template, as mrpt::math::ransac_detect_2D_lines does it (same
 * model, distance, minimal set of 2 points, probability 0.99999, same random
 * stream), but with the verbosity of MRPT's RANSAC logger (a COutputLogger)
 * chosen by the caller: MRPT's function hard-codes LVL_INFO and prints
 * "Finished in N iterations" for every line it looks for. */
#pragma once

#include <mrpt/math/CVectorDynamic.h>
#include <mrpt/math/TLine2D.h>
#include <mrpt/system/COutputLogger.h>

#include <utility>
#include <vector>

namespace hslam::features::detail
{
/** Lines (inlier count, unit line) found one after another, each from the
 * points the previous ones left, until one has fewer than `minInliers`. */
std::vector<std::pair<size_t, mrpt::math::TLine2D>> detectRansacLines(const mrpt::math::CVectorDynamic<double>& xs,
																	   const mrpt::math::CVectorDynamic<double>& ys,
																	   double threshold_m, size_t minInliers,
																	   mrpt::system::VerbosityLevel verbosity);
}  // namespace hslam::features::detail
