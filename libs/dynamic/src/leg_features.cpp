#include <hslam/dynamic/leg_features.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace hslam::dynamic
{
namespace
{
using mrpt::math::TPoint2D;

constexpr double kNoReturnGap_m = 2.0;

double distance(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

double medianOf(std::vector<double> v)
{
	std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
	return v[v.size() / 2];
}

/** Sum of squared orthogonal residuals of the total-least-squares line. */
double lineResidual(const std::vector<TPoint2D>& pts, const TPoint2D& c)
{
	double sxx = 0, syy = 0, sxy = 0;
	for (const auto& p : pts)
	{
		sxx += (p.x - c.x) * (p.x - c.x);
		syy += (p.y - c.y) * (p.y - c.y);
		sxy += (p.x - c.x) * (p.y - c.y);
	}
	// Smallest eigenvalue of the scatter matrix.
	return 0.5 * (sxx + syy - std::sqrt((sxx - syy) * (sxx - syy) + 4 * sxy * sxy));
}

/** Algebraic (Kasa) circle fit x^2 + y^2 + D x + E y + F = 0 around the
 * centroid; returns {sum of squared radial residuals, radius}. */
std::pair<double, double> circleFit(const std::vector<TPoint2D>& pts, const TPoint2D& c)
{
	Eigen::MatrixXd A(pts.size(), 3);
	Eigen::VectorXd b(pts.size());
	for (size_t i = 0; i < pts.size(); ++i)
	{
		const double x = pts[i].x - c.x, y = pts[i].y - c.y;
		A.row(static_cast<long>(i)) << x, y, 1.0;
		b(static_cast<long>(i)) = -(x * x + y * y);
	}
	const Eigen::Vector3d s = A.colPivHouseholderQr().solve(b);
	const double cx = -s(0) / 2, cy = -s(1) / 2;
	const double r2 = cx * cx + cy * cy - s(2);
	constexpr double kMaxRadius_m = 10.0;
	if (!(r2 > 0) || !std::isfinite(r2)) return {lineResidual(pts, c), kMaxRadius_m};
	const double r = std::min(kMaxRadius_m, std::sqrt(r2));
	double residual = 0;
	for (const auto& p : pts)
	{
		const double e = std::hypot(p.x - c.x - cx, p.y - c.y - cy) - r;
		residual += e * e;
	}
	return {residual, r};
}

/** Range of the nearest valid beam beyond the edge (looking at most
 * kGapSearchBeams out: Hokuyos report 0 for the mixed pixels at an edge)
 * minus the edge beam's range, clamped; none counts as far behind. */
double edgeGap(const mrpt::obs::CObservation2DRangeScan& scan, size_t edge, int direction)
{
	constexpr int kGapSearchBeams = 3;
	for (int k = 1; k <= kGapSearchBeams; ++k)
	{
		const long n = static_cast<long>(edge) + direction * k;
		if (n < 0 || n >= static_cast<long>(scan.getScanSize())) break;
		const double r = scan.getScanRange(static_cast<size_t>(n));
		if (!scan.getScanRangeValidity(static_cast<size_t>(n)) || !std::isfinite(r) || r <= 0) continue;
		return std::clamp(r - static_cast<double>(scan.getScanRange(edge)), -kNoReturnGap_m, kNoReturnGap_m);
	}
	return kNoReturnGap_m;
}
}  // namespace

const char* legFeatureName(size_t k)
{
	static const char* names[kLegFeatureCount] = {
		"points",         "std_dev_m",        "median_deviation_m", "width_m",          "linearity_m2",
		"circularity_m2", "radius_m",         "boundary_length_m",  "boundary_regularity_m", "mean_curvature_1pm",
		"mean_angle_diff_rad", "range_m",     "gap_before_m",       "gap_after_m",
		"missing_beams",  "neighbour_m",      "neighbour_width_m",  "neighbours_1m"};
	return k < kLegFeatureCount ? names[k] : "?";
}

namespace
{
/** The nearest other cluster (centroid distance, capped at 3 m, and its end-to-end
 * width) and how many clusters have their centroid within 1 m. */
struct TNeighbourhood
{
	double nearest_m = 3.0, nearest_width_m = 0;
	int crowd = 0;
};

TNeighbourhood neighbourhood(const std::vector<TScanCluster>& clusters, size_t k)
{
	constexpr double kCrowd_m = 1.0;
	const TPoint2D& c = clusters[k].centroid;
	TNeighbourhood out;
	for (size_t j = 0; j < clusters.size(); ++j)
	{
		if (j == k) continue;
		const double d = distance(c, clusters[j].centroid);
		out.crowd += d < kCrowd_m;
		if (d < out.nearest_m)
		{
			out.nearest_m = d;
			out.nearest_width_m = distance(clusters[j].points.front(), clusters[j].points.back());
		}
	}
	return out;
}

/** Standard deviation of the points' distances from the centroid `c`. */
double spreadStdDev_m(const std::vector<TPoint2D>& pts, const TPoint2D& c)
{
	double var = 0;
	for (const auto& p : pts) var += (p.x - c.x) * (p.x - c.x) + (p.y - c.y) * (p.y - c.y);
	return pts.size() > 1 ? std::sqrt(var / static_cast<double>(pts.size() - 1)) : 0.0;
}

/** Mean distance of the points from their coordinate-wise median. */
double meanDeviationFromMedian_m(const std::vector<TPoint2D>& pts)
{
	std::vector<double> xs, ys;
	for (const auto& p : pts) xs.push_back(p.x), ys.push_back(p.y);
	const TPoint2D median{medianOf(xs), medianOf(ys)};
	double medianDev = 0;
	for (const auto& p : pts) medianDev += distance(p, median);
	return medianDev / static_cast<double>(pts.size());
}

/** Length of the polyline through the points and the standard deviation of its steps. */
struct TContour
{
	double length_m = 0, regularity_m = 0;
};

TContour contour(const std::vector<TPoint2D>& pts)
{
	TContour out;
	double stepSq = 0;
	for (size_t i = 1; i < pts.size(); ++i)
	{
		const double d = distance(pts[i], pts[i - 1]);
		out.length_m += d;
		stepSq += d * d;
	}
	const double steps = static_cast<double>(std::max<size_t>(1, pts.size() - 1));
	const double meanStep = out.length_m / steps;
	out.regularity_m = std::sqrt(std::max(0.0, stepSq / steps - meanStep * meanStep));
	return out;
}

/** Mean over consecutive point triples of the circumcircle curvature and of the turning angle. */
struct TBending
{
	double curvature_per_m = 0, angle_rad = 0;
};

TBending meanBending(const std::vector<TPoint2D>& pts)
{
	const size_t n = pts.size();
	double curvature = 0, angleDiff = 0;
	for (size_t i = 1; i + 1 < n; ++i)
	{
		const TPoint2D &a = pts[i - 1], &b = pts[i], &d = pts[i + 1];
		const double ab = distance(a, b), bd = distance(b, d), ad = distance(a, d);
		const double cross = (b.x - a.x) * (d.y - b.y) - (b.y - a.y) * (d.x - b.x);
		if (ab * bd * ad > 1e-12) curvature += 2 * std::abs(cross) / (ab * bd * ad);  // 4 * area / product
		angleDiff += std::abs(std::atan2(cross, (b.x - a.x) * (d.x - b.x) + (b.y - a.y) * (d.y - b.y)));
	}
	const double triples = static_cast<double>(std::max<size_t>(1, n - 2));
	return {curvature / triples, angleDiff / triples};
}
}  // namespace

TLegFeatures legFeatures(const std::vector<TScanCluster>& clusters, size_t k,
						 const mrpt::obs::CObservation2DRangeScan& scan)
{
	const TScanCluster& cluster = clusters.at(k);
	const auto& pts = cluster.points;
	const size_t n = pts.size();
	const TPoint2D& c = cluster.centroid;
	const TNeighbourhood around = neighbourhood(clusters, k);
	const auto [circularity, radius] = circleFit(pts, c);
	const TContour outline = contour(pts);
	const TBending bending = meanBending(pts);
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	const size_t first = cluster.firstBeam(), last = cluster.lastBeam();
	return {static_cast<float>(n),
			static_cast<float>(spreadStdDev_m(pts, c)),
			static_cast<float>(meanDeviationFromMedian_m(pts)),
			static_cast<float>(distance(pts.front(), pts.back())),
			static_cast<float>(lineResidual(pts, c)),
			static_cast<float>(circularity),
			static_cast<float>(radius),
			static_cast<float>(outline.length_m),
			static_cast<float>(outline.regularity_m),
			static_cast<float>(bending.curvature_per_m),
			static_cast<float>(bending.angle_rad),
			static_cast<float>(std::hypot(c.x - sx, c.y - sy)),
			static_cast<float>(edgeGap(scan, first, -1)),
			static_cast<float>(edgeGap(scan, last, +1)),
			static_cast<float>(last - first + 1 - n),
			static_cast<float>(around.nearest_m),
			static_cast<float>(around.nearest_width_m),
			static_cast<float>(around.crowd)};
}

}  // namespace hslam::dynamic
