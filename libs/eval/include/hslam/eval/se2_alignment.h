/* hslam: closed-form least-squares rigid 2D alignment of two point sets
 * (Horn / Umeyama without scale, specialised to SE(2)). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::eval
{
/** The rigid transform T (rotation + translation, no scale) minimising
 * sum_k |T (+) from[k] - to[k]|^2. With centred points a_k, b_k the angle is
 * atan2(sum a_k x b_k, sum a_k . b_k) and the translation maps the centroid
 * of `from` onto that of `to`. Computed in double precision (MRPT's
 * mrpt::tfest::se2_l2 works on float pairs, too coarse for world-frame
 * coordinates). Degenerate input (all `from` points equal) gives angle 0.
 * Throws std::invalid_argument if the sizes differ or are zero. */
mrpt::poses::CPose2D alignPointsSE2(const std::vector<mrpt::math::TPoint2D>& from,
									const std::vector<mrpt::math::TPoint2D>& to);

}  // namespace hslam::eval
