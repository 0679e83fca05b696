#include <hslam/dynamic/CLegDetector.h>
#include <hslam/dynamic/leg_clusters.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hslam::dynamic
{
namespace
{
struct TValidBeam
{
	size_t index;
	double range_m;
	mrpt::math::TPoint2D p;
};

std::vector<TValidBeam> validBeams(const mrpt::obs::CObservation2DRangeScan& scan, double maxRange_m)
{
	std::vector<TValidBeam> out;
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y();
	for (size_t i = 0; i < scan.getScanSize(); ++i)
	{
		const double r = scan.getScanRange(i);
		if (!scan.getScanRangeValidity(i) || !std::isfinite(r) || r <= 0 || r > maxRange_m) continue;
		const double a = beamBearing(scan, i);
		out.push_back({i, r, {sx + r * std::cos(a), sy + r * std::sin(a)}});
	}
	return out;
}

size_t findRoot(std::vector<size_t>& parent, size_t i)
{
	while (parent[i] != i) i = parent[i] = parent[parent[i]];
	return i;
}
}  // namespace

std::vector<TScanCluster> clusterScan(const mrpt::obs::CObservation2DRangeScan& scan, const TClusterOptions& options)
{
	const auto beams = validBeams(scan, options.max_range_m);
	const double step = std::max(1e-9, angularStep(scan));
	const double d = options.cluster_distance_m;
	// Union-find over the neighbour relation "closer than d and within the
	// beams d subtends at this range" (the flood fill of the file comment).
	std::vector<size_t> parent(beams.size());
	std::iota(parent.begin(), parent.end(), 0);
	for (size_t a = 0; a < beams.size(); ++a)
	{
		const double ratio = std::min(1.0, d / beams[a].range_m);
		const size_t window = 1 + static_cast<size_t>(std::asin(ratio) / step);
		for (size_t b = a + 1; b < beams.size() && beams[b].index <= beams[a].index + window; ++b)
			if (std::hypot(beams[b].p.x - beams[a].p.x, beams[b].p.y - beams[a].p.y) < d)
				parent[findRoot(parent, b)] = findRoot(parent, a);
	}
	std::vector<TScanCluster> clusters;
	std::vector<long> clusterOfRoot(beams.size(), -1);
	for (size_t a = 0; a < beams.size(); ++a)
	{
		const size_t root = findRoot(parent, a);
		if (clusterOfRoot[root] < 0)
		{
			clusterOfRoot[root] = static_cast<long>(clusters.size());
			clusters.emplace_back();
		}
		auto& c = clusters[static_cast<size_t>(clusterOfRoot[root])];
		c.beams.push_back(beams[a].index);
		c.points.push_back(beams[a].p);
	}
	for (auto& c : clusters)
	{
		c.centroid = {0, 0};
		for (const auto& p : c.points) c.centroid.x += p.x, c.centroid.y += p.y;
		c.centroid.x /= static_cast<double>(c.points.size());
		c.centroid.y /= static_cast<double>(c.points.size());
	}
	clusters.erase(std::remove_if(clusters.begin(), clusters.end(),
								  [&](const TScanCluster& c) { return static_cast<int>(c.points.size()) < options.min_points; }),
				   clusters.end());
	std::sort(clusters.begin(), clusters.end(),
			  [](const TScanCluster& a, const TScanCluster& b) { return a.firstBeam() < b.firstBeam(); });
	return clusters;
}

}  // namespace hslam::dynamic
