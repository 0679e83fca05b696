#include <hslam/vision/optical_flow.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include <cmath>
#include <stdexcept>

namespace hslam::vision
{
std::vector<cv::Point2f> detectCorners(const cv::Mat& grey, const TFlowOptions& o)
{
	cv::Mat mask(grey.size(), CV_8UC1, cv::Scalar(0));
	const int b = std::min(o.border_px, std::min(grey.cols, grey.rows) / 4);
	mask(cv::Rect(b, b, grey.cols - 2 * b, grey.rows - 2 * b)).setTo(255);
	std::vector<cv::Point2f> corners;
	cv::goodFeaturesToTrack(grey, corners, o.max_corners, o.corner_quality, o.corner_min_distance_px, mask);
	return corners;
}

namespace
{
bool inside(const cv::Point2f& p, const cv::Size& s)
{
	return p.x >= 0 && p.y >= 0 && p.x <= s.width - 1 && p.y <= s.height - 1;
}

void checkPair(const cv::Mat& prevGrey, const cv::Mat& currGrey)
{
	if (prevGrey.type() != CV_8UC1 || currGrey.type() != CV_8UC1 || prevGrey.size() != currGrey.size() ||
		prevGrey.empty())
		throw std::invalid_argument("trackFeatures: two non-empty 8-bit grey images of the same size are needed");
}
}  // namespace

TFlowResult trackFeatures(const cv::Mat& prevGrey, const cv::Mat& currGrey, const TFlowOptions& o)
{
	checkPair(prevGrey, currGrey);
	return trackCorners(prevGrey, currGrey, detectCorners(prevGrey, o), o);
}

TFlowResult trackCorners(const cv::Mat& prevGrey, const cv::Mat& currGrey, const std::vector<cv::Point2f>& p0,
						 const TFlowOptions& o)
{
	checkPair(prevGrey, currGrey);
	TFlowResult out;
	out.corners = p0.size();
	if (p0.empty()) return out;
	const cv::Size window(o.lk_window_px, o.lk_window_px);
	const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
	std::vector<cv::Point2f> p1, back;
	std::vector<uchar> status, backStatus;
	std::vector<float> err;
	cv::calcOpticalFlowPyrLK(prevGrey, currGrey, p0, p1, status, err, window, o.lk_pyramid_levels, stop);
	const bool checkBack = o.fb_max_error_px > 0;
	if (checkBack)
		cv::calcOpticalFlowPyrLK(currGrey, prevGrey, p1, back, backStatus, err, window, o.lk_pyramid_levels, stop);
	for (size_t i = 0; i < p0.size(); ++i)
	{
		if (!status[i] || !inside(p1[i], currGrey.size()))
		{
			++out.lost;
			continue;
		}
		if (checkBack && (!backStatus[i] || cv::norm(back[i] - p0[i]) > o.fb_max_error_px))
		{
			++out.fb_rejected;
			continue;
		}
		out.vectors.push_back({p0[i], p1[i]});
	}
	return out;
}

double flowMagnitudeRms(const std::vector<cv::Point2f>& flow)
{
	if (flow.empty()) return 0.0;
	double s = 0;
	for (const auto& f : flow) s += f.dot(f);
	return std::sqrt(s / static_cast<double>(flow.size()));
}

}  // namespace hslam::vision
