#include <hslam/vision/vision_drawing.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace hslam::vision
{
namespace
{
const cv::Scalar kYellow(0, 220, 255), kCyan(255, 200, 0), kGreen(0, 200, 0), kRed(0, 0, 255), kBlue(255, 80, 0);

cv::Mat toBgr(const cv::Mat& grey)
{
	cv::Mat bgr;
	cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
	return bgr;
}

void arrow(cv::Mat& img, const cv::Point2f& a, const cv::Point2f& b, const cv::Scalar& colour)
{
	cv::circle(img, a, 2, colour, 1, cv::LINE_AA);
	cv::line(img, a, b, colour, 1, cv::LINE_AA);
}

void label(cv::Mat& img, const std::string& text)
{
	cv::putText(img, text, {6, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 3, cv::LINE_AA);
	cv::putText(img, text, {6, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
}

void drawFoe(cv::Mat& img, const TFrameAnalysis& a)
{
	if (a.vote.valid_x)
		cv::rectangle(img, cv::Rect(static_cast<int>(a.vote.x_px) - 5, static_cast<int>(a.vote.y_px) - 5, 10, 10), kBlue,
					  2);
	if (a.foe.valid)
		cv::drawMarker(img, cv::Point2f(static_cast<float>(a.foe.x_px), static_cast<float>(a.foe.y_px)), kRed,
					   cv::MARKER_CROSS, 16, 2);
}

cv::Mat votePanel(const cv::Mat& grey, const TFrameAnalysis& a)
{
	cv::Mat img = toBgr(grey);
	const auto& sums = a.vote.column_sums;
	const double maxAbs = std::max(1.0, std::abs(*std::max_element(sums.begin(), sums.end(), [](double x, double y) {
		return std::abs(x) < std::abs(y);
	})));
	const int n = static_cast<int>(sums.size()), w = img.cols, base = img.rows * 3 / 4;
	for (int i = 0; i < n; ++i)
	{
		const int x0 = i * w / n, x1 = (i + 1) * w / n;
		cv::line(img, {x0, 0}, {x0, img.rows}, cv::Scalar(128, 128, 128), 1);
		const int h = static_cast<int>(sums[static_cast<size_t>(i)] / maxAbs * img.rows / 5);
		cv::rectangle(img, cv::Point(x0 + 3, base), cv::Point(x1 - 3, base - h), h >= 0 ? kGreen : kRed, cv::FILLED);
	}
	cv::line(img, {0, base}, {w, base}, cv::Scalar(255, 255, 255), 1);
	drawFoe(img, a);
	label(img, "column votes, FOE: vote (square) / least squares (cross)");
	return img;
}
}  // namespace

cv::Mat drawAnalysisPanels(const cv::Mat& grey, const TFrameAnalysis& a)
{
	cv::Mat flow = toBgr(grey), predicted = toBgr(grey), residual = toBgr(grey);
	std::vector<uint8_t> bad(a.residual.size(), 0);
	for (size_t i : a.inconsistent) bad[i] = 1;
	for (size_t i = 0; i < a.flow.vectors.size(); ++i)
	{
		const auto& f = a.flow.vectors[i];
		arrow(flow, f.p0, f.p1, kYellow);
		arrow(predicted, f.p0, f.p0 + a.predicted[i], kCyan);
		const auto& r = a.residual[i];
		arrow(residual, r.p0, r.p1, bad[i] ? kRed : (a.foe.valid && a.foe.inlier[i] ? kGreen : kCyan));
	}
	for (const auto& reg : a.regions) cv::rectangle(residual, reg.box, kRed, 2);
	drawFoe(residual, a);
	label(flow, "optical flow (" + std::to_string(a.flow.vectors.size()) + " tracks)");
	label(predicted, "predicted rotation flow");
	label(residual, "residual: FOE inliers green, inconsistent red");
	cv::Mat top, bottom, out;
	cv::hconcat(flow, predicted, top);
	cv::hconcat(residual, votePanel(grey, a), bottom);
	cv::vconcat(top, bottom, out);
	return out;
}

}  // namespace hslam::vision
