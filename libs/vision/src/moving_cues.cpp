#include <hslam/vision/moving_cues.h>

#include <algorithm>
#include <cmath>

namespace hslam::vision
{
std::vector<size_t> inconsistentVectors(const std::vector<TFlowVector>& residual, const TFoeEstimate& foe,
										const TFoeOptions& o)
{
	// Without a trustworthy FOE (robot turning or at rest) only clearly moving vectors count.
	const bool useFoe = foe.valid && foe.confidence >= kMinFoeConfidence;
	const double minLength_px = useFoe ? o.minFlow_px() : kNoFoeLengthFactor * o.minFlow_px();
	std::vector<size_t> out;
	for (size_t i = 0; i < residual.size(); ++i)
	{
		if (cv::norm(residual[i].flow()) < minLength_px) continue;
		if (!useFoe || i >= foe.inlier.size() || !foe.inlier[i]) out.push_back(i);
	}
	return out;
}

namespace
{
TMovingRegion regionOf(const std::vector<TFlowVector>& residual, const std::vector<size_t>& members,
					   const TMountedCamera& camera)
{
	TMovingRegion r;
	float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f;
	for (size_t i : members)
	{
		const cv::Point2f p = residual[i].p1;
		r.centre += p;
		r.mean_residual_px += cv::norm(residual[i].flow());
		x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
	}
	r.vectors = members.size();
	r.centre *= 1.0f / static_cast<float>(members.size());
	r.mean_residual_px /= static_cast<double>(members.size());
	r.box = cv::Rect2f(x0, y0, x1 - x0, y1 - y0);
	r.bearing_rad = robotBearingOfPixel(camera, r.centre.x, r.centre.y);
	const double a = robotBearingOfPixel(camera, x0, r.centre.y), b = robotBearingOfPixel(camera, x1, r.centre.y);
	r.bearing_min_rad = std::min(a, b);
	r.bearing_max_rad = std::max(a, b);
	return r;
}
}  // namespace

std::vector<TMovingRegion> findMovingRegions(const std::vector<TFlowVector>& residual,
											 const std::vector<size_t>& inconsistent, const TMountedCamera& camera,
											 const TMovingCueOptions& o)
{
	std::vector<cv::Point2f> points;
	for (size_t i : inconsistent) points.push_back(residual[i].p1);
	std::vector<int> labels;
	const double d2 = o.cluster_distance_px * o.cluster_distance_px;
	const int n = cv::partition(points, labels, [d2](const cv::Point2f& a, const cv::Point2f& b) {
		const cv::Point2f d = a - b;
		return d.dot(d) <= d2;
	});
	std::vector<std::vector<size_t>> groups(static_cast<size_t>(n));
	for (size_t k = 0; k < labels.size(); ++k) groups[static_cast<size_t>(labels[k])].push_back(inconsistent[k]);
	std::vector<TMovingRegion> out;
	for (const auto& g : groups)
		if (static_cast<int>(g.size()) >= o.min_vectors) out.push_back(regionOf(residual, g, camera));
	std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.vectors > b.vectors; });
	return out;
}

}  // namespace hslam::vision
