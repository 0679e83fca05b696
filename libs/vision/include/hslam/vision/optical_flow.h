/* hslam vision: sparse optical flow between two grey images (thesis 4.8.2 i,
 * appendix I.2): Shi-Tomasi corners (cv::goodFeaturesToTrack; the thesis used
 * 300 corners, quality 0.01, 10 px apart) tracked by pyramidal Lucas-Kanade
 * (cv::calcOpticalFlowPyrLK). Beyond the thesis, whose 4.8.4 names unstable
 * features as the reason the camera failed on the moving robot, every track
 * is checked forward-backward: the second point is tracked back into the
 * first image and the track is dropped if it does not come back within
 * fb_max_error_px (Kalal et al., "Forward-backward error", ICPR 2010). */
#pragma once

#include <opencv2/core.hpp>

#include <vector>

namespace hslam::vision
{
struct TFlowOptions  //!< [vision] keys of the tracker
{
	int max_corners = 300;  //!< appendix I.2
	double corner_quality = 0.01;  //!< relative to the best corner (appendix I.2)
	double corner_min_distance_px = 10;  //!< appendix I.2, at 640 x 480
	int lk_window_px = 21;  //!< Lucas-Kanade window side
	int lk_pyramid_levels = 3;  //!< pyramid levels above the full image
	double fb_max_error_px = 1.0;  //!< forward-backward check (0 = off)
	int border_px = 4;  //!< corners this close to the border are not used

	template <class V>
	void visit(V& v)
	{
		v.integer("max_corners", max_corners, 4, 10000);
		v.real("corner_quality", corner_quality, 1e-4, 1.0);
		v.real("corner_min_distance_px", corner_min_distance_px, 1.0, 200.0);
		v.integer("lk_window_px", lk_window_px, 5, 101);
		v.integer("lk_pyramid_levels", lk_pyramid_levels, 0, 8);
		v.real("fb_max_error_px", fb_max_error_px, 0.0, 50.0);
		v.integer("border_px", border_px, 0, 100);
	}
};

/** One tracked corner: position in the first image and in the second. */
struct TFlowVector
{
	cv::Point2f p0, p1;
	cv::Point2f flow() const { return p1 - p0; }
};

struct TFlowResult
{
	std::vector<TFlowVector> vectors;  //!< tracks that passed every check
	size_t corners = 0;  //!< corners detected in the first image
	size_t lost = 0;  //!< not found by Lucas-Kanade
	size_t fb_rejected = 0;  //!< failed the forward-backward check
};

/** Corners of `prevGrey` tracked into `currGrey` (both CV_8UC1, same size;
 * throws std::invalid_argument otherwise): detectCorners then trackCorners. */
TFlowResult trackFeatures(const cv::Mat& prevGrey, const cv::Mat& currGrey, const TFlowOptions& options);

/** The Shi-Tomasi corners of one grey image (not within border_px of its edge). */
std::vector<cv::Point2f> detectCorners(const cv::Mat& grey, const TFlowOptions& options);

/** Lucas-Kanade tracks of `corners` from `prevGrey` into `currGrey` with the
 * forward-backward check (same image checks as trackFeatures). */
TFlowResult trackCorners(const cv::Mat& prevGrey, const cv::Mat& currGrey, const std::vector<cv::Point2f>& corners,
						 const TFlowOptions& options);

/** Root mean square of the vector lengths (px); 0 for none. The noise floor
 * of thesis 4.8.2 iv is this at rest (0.2 px there). */
double flowMagnitudeRms(const std::vector<cv::Point2f>& flow);

}  // namespace hslam::vision
