#include <hslam/fusion/se2.h>
#include <hslam/features/scan_points.h>
#include <hslam/slam/pose_plots.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace hslam::slam
{
namespace
{
const mrpt::img::TColor kBackground{255, 255, 255}, kAxes{80, 80, 80}, kGridLine{225, 225, 225};
const mrpt::img::TColor kEstimate{220, 20, 20}, kSigma{245, 160, 160}, kOdometry{255, 150, 0};

struct TPanel
{
	int top = 0, height = 0, left = 70, right = 0;
	double t0 = 0, t1 = 1, v0 = 0, v1 = 1;
	int px(double t) const { return left + static_cast<int>((t - t0) / (t1 - t0) * (right - left)); }
	int py(double v) const { return top + height - 20 - static_cast<int>((v - v0) / (v1 - v0) * (height - 40)); }
};

std::string formatNumber(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.3g", v);
	return buf;
}

void drawSeries(mrpt::img::CImage& img, const TPanel& p, const std::vector<double>& t, const std::vector<double>& v,
				const mrpt::img::TColor& colour)
{
	for (size_t i = 1; i < t.size(); ++i)
		img.line(p.px(t[i - 1]), p.py(v[i - 1]), p.px(t[i]), p.py(v[i]), colour, 1);
}

void drawPanelFrame(mrpt::img::CImage& img, const TPanel& p, const std::string& title)
{
	for (int k = 0; k <= 4; ++k)
	{
		const double v = p.v0 + (p.v1 - p.v0) * k / 4.0;
		img.line(p.left, p.py(v), p.right, p.py(v), kGridLine, 1);
		img.textOut(4, p.py(v) - 6, formatNumber(v), kAxes);
	}
	img.rectangle(p.left, p.py(p.v1), p.right, p.py(p.v0), kAxes, 1);
	img.textOut(p.left + 6, p.top + 2, title, kAxes);
	img.textOut(p.right - 160, p.py(p.v0) + 4, "0 .. " + formatNumber(p.t1 - p.t0) + " s", kAxes);
}

/** Continuous angle sequence (deg): removes the +-180 jumps so a plot shows turns, not wraps. */
std::vector<double> unwrappedDegrees(const std::vector<double>& wrappedRad)
{
	std::vector<double> out;
	double offset = 0;
	for (size_t i = 0; i < wrappedRad.size(); ++i)
	{
		if (i > 0) offset += fusion::wrapToPi(wrappedRad[i] - wrappedRad[i - 1]) - (wrappedRad[i] - wrappedRad[i - 1]);
		out.push_back((wrappedRad[i] + offset) * 180.0 / M_PI);
	}
	return out;
}

/** Range of the values (and value +- sigma) with a small margin. */
std::pair<double, double> valueRange(const std::vector<double>& a, const std::vector<double>& b,
									 const std::vector<double>& sigma)
{
	double lo = 1e300, hi = -1e300;
	for (size_t i = 0; i < a.size(); ++i) lo = std::min(lo, a[i] - sigma[i]), hi = std::max(hi, a[i] + sigma[i]);
	for (double v : b) lo = std::min(lo, v), hi = std::max(hi, v);
	if (!(hi > lo)) lo -= 1, hi += 1;
	const double m = 0.05 * (hi - lo);
	return {lo - m, hi + m};
}
}  // namespace

mrpt::img::CImage renderPosePlot(const std::vector<CMappingPipeline::TTimedEstimate>& estimates,
								 const common::TTrajectory2D& odometry, int widthPx, int panelHeightPx)
{
	constexpr int kPanels = 4;
	mrpt::img::CImage img(widthPx, kPanels * panelHeightPx, mrpt::img::CH_RGB);
	img.filledRectangle(0, 0, widthPx - 1, kPanels * panelHeightPx - 1, kBackground);
	if (estimates.empty()) return img;
	std::vector<double> t, odoT, phi, odoPhi;
	for (const auto& e : estimates) t.push_back(e.t_s), phi.push_back(e.estimate.pose.phi());
	for (const auto& o : odometry) odoT.push_back(o.t_s), odoPhi.push_back(o.pose.phi);
	const std::vector<double> phiDeg = unwrappedDegrees(phi), odoPhiDeg = unwrappedDegrees(odoPhi);
	const double t0 = t.front(), t1 = std::max(t.back(), t0 + 1e-3);
	const auto panel = [&](int k) {
		TPanel p;
		p.top = k * panelHeightPx;
		p.height = panelHeightPx;
		p.right = widthPx - 10;
		p.t0 = t0, p.t1 = t1;
		return p;
	};
	const char* titles[3] = {"x (m): estimate (red) +-1 sigma (pink), odometry (orange)", "y (m)",
							 "theta (deg, unwrapped)"};
	for (int k = 0; k < 3; ++k)
	{
		std::vector<double> v, s, lo, hi, odo;
		for (size_t i = 0; i < estimates.size(); ++i)
		{
			const auto& e = estimates[i].estimate;
			const double scale = k == 2 ? 180.0 / M_PI : 1.0;
			v.push_back(k == 0 ? e.pose.x() : k == 1 ? e.pose.y() : phiDeg[i]);
			s.push_back(std::sqrt(std::max(0.0, e.covariance(k, k))) * scale);
			lo.push_back(v.back() - s.back());
			hi.push_back(v.back() + s.back());
		}
		for (size_t i = 0; i < odometry.size(); ++i)
			odo.push_back(k == 0 ? odometry[i].pose.x : k == 1 ? odometry[i].pose.y : odoPhiDeg[i]);
		TPanel p = panel(k);
		std::tie(p.v0, p.v1) = valueRange(v, odo, s);
		drawPanelFrame(img, p, titles[k]);
		drawSeries(img, p, t, lo, kSigma);
		drawSeries(img, p, t, hi, kSigma);
		drawSeries(img, p, odoT, odo, kOdometry);
		drawSeries(img, p, t, v, kEstimate);
	}
	// Standard deviations themselves (thesis figures 117-127 plot the covariances).
	std::vector<double> sxy, sth, zero;
	for (const auto& e : estimates)
	{
		sxy.push_back(100.0 * std::sqrt(std::max({0.0, e.estimate.covariance(0, 0), e.estimate.covariance(1, 1)})));
		sth.push_back(180.0 / M_PI * std::sqrt(std::max(0.0, e.estimate.covariance(2, 2))));
		zero.push_back(0.0);
	}
	TPanel p = panel(3);
	std::tie(p.v0, p.v1) = valueRange(sxy, sth, zero);
	p.v0 = 0;
	drawPanelFrame(img, p, "std: position (cm, red), heading (deg, blue)");
	drawSeries(img, p, t, sxy, kEstimate);
	drawSeries(img, p, t, sth, mrpt::img::TColor(30, 60, 220));
	return img;
}

mrpt::img::CImage renderScanDebugImage(const mrpt::obs::CObservation2DRangeScan& scan, const TPoseEstimate& estimate,
									   double halfWidth_m, int sizePx)
{
	mrpt::img::CImage img(sizePx, sizePx, mrpt::img::CH_RGB);
	img.filledRectangle(0, 0, sizePx - 1, sizePx - 1, kBackground);
	const double pxPerM = 0.5 * sizePx / halfWidth_m;
	const auto col = [&](double x) { return static_cast<int>(0.5 * sizePx + x * pxPerM); };
	const auto row = [&](double y) { return static_cast<int>(0.5 * sizePx - y * pxPerM); };
	for (int m = -static_cast<int>(halfWidth_m); m <= static_cast<int>(halfWidth_m); ++m)
	{
		img.line(col(m), 0, col(m), sizePx - 1, kGridLine, 1);
		img.line(0, row(m), sizePx - 1, row(m), kGridLine, 1);
	}
	img.drawCircle(col(0), row(0), 6, kAxes, 1);
	img.line(col(0), row(0), col(0.5), row(0), kAxes, 1);  // heading: robot x axis points right
	for (const auto& p : common::makeRangeData(scan).points.xy)
		img.filledRectangle(col(p.x) - 1, row(p.y) - 1, col(p.x) + 1, row(p.y) + 1, mrpt::img::TColor(200, 30, 30));
	for (const auto& l : estimate.lines)
	{
		img.line(col(l.p0.x), row(l.p0.y), col(l.p1.x), row(l.p1.y), mrpt::img::TColor(20, 60, 220), 2);
		img.drawMark(col(l.p0.x), row(l.p0.y), mrpt::img::TColor(0, 150, 0), '+', 5, 2);
		img.drawMark(col(l.p1.x), row(l.p1.y), mrpt::img::TColor(0, 150, 0), '+', 5, 2);
	}
	char caption[160];
	std::snprintf(caption, sizeof(caption), "%zu lines  match: %s %s%s  NIS %.2f  1 grid = 1 m", estimate.lines.size(),
				  estimate.matched ? estimate.match_method.c_str() : "-",
				  estimate.matched ? matching::toString(estimate.match_quality) : "",
				  estimate.matched && !estimate.match_accepted && estimate.match_quality != matching::EMatchQuality::failed
					  ? " (rejected)"
					  : "",
				  estimate.match_nis);
	img.textOut(6, 6, caption, kAxes);
	return img;
}

}  // namespace hslam::slam
