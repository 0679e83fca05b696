/* hslam vision: debug pictures like thesis figures 172 and 178-184, drawn
 * into images (the caller writes them):
 *  - flow vectors: circles at the corners of the first image, lines to the
 *    second (figure 172 / 178);
 *  - predicted rotation flow (figure 179);
 *  - residual after removal: FOE inliers green, inconsistent vectors red,
 *    moving regions boxed (figure 181);
 *  - column votes (bars under the image) with the vote FOE (square) and the
 *    least-squares FOE (cross) (figures 182-184). */
#pragma once

#include <hslam/vision/CFlowAnalyzer.h>

namespace hslam::vision
{
/** 2 x 2 mosaic (BGR) of the four panels above, on the second image. */
cv::Mat drawAnalysisPanels(const cv::Mat& currGrey, const TFrameAnalysis& analysis);

}  // namespace hslam::vision
