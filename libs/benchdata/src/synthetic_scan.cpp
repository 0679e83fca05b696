/* hslam: exact ray-cast scans of wall segments (see synthetic_scan.h). */
#include <hslam/benchdata/synthetic_scan.h>

#include <cmath>
#include <random>

namespace hslam::benchdata
{
namespace
{
/** Distance along the ray (origin o, unit direction d) to segment ab, or -1. */
double rayHit(const mrpt::math::TPoint2D& o, double dx, double dy, const TWall& w)
{
	const double ex = w.b.x - w.a.x, ey = w.b.y - w.a.y;
	const double denom = dx * ey - dy * ex;
	if (std::abs(denom) < 1e-12) return -1;  // parallel
	const double ox = w.a.x - o.x, oy = w.a.y - o.y;
	const double t = (ox * ey - oy * ex) / denom;  // along the ray
	const double s = (ox * dy - oy * dx) / denom;  // along the wall, [0, 1]
	if (t <= 0 || s < 0 || s > 1) return -1;
	return t;
}
}  // namespace

double TVisibleWall::length_m() const { return std::hypot(p1.x - p0.x, p1.y - p0.y); }

TSyntheticScan simulateScan(const std::vector<TWall>& walls, const mrpt::poses::CPose2D& robotPose,
							const TScanLayout& layout, uint32_t noiseSeed)
{
	TSyntheticScan sim;
	auto& scan = sim.scan;
	scan.aperture = static_cast<float>(layout.aperture_rad);
	scan.rightToLeft = true;
	scan.maxRange = static_cast<float>(layout.max_range_m);
	scan.sensorLabel = "LASER";
	scan.resizeScan(layout.beams);
	sim.wall_of_beam.assign(layout.beams, -1);
	sim.true_range_m.assign(layout.beams, 0);
	std::mt19937 rng(noiseSeed);
	const mrpt::math::TPoint2D origin(robotPose.x(), robotPose.y());
	for (size_t i = 0; i < layout.beams; ++i)
	{
		const double a = robotPose.phi() + scan.getScanAngle(i);
		const double dx = std::cos(a), dy = std::sin(a);
		double best = layout.max_range_m;
		for (size_t w = 0; w < walls.size(); ++w)
		{
			const double t = rayHit(origin, dx, dy, walls[w]);
			if (t > 0 && t < best)
			{
				best = t;
				sim.wall_of_beam[i] = static_cast<int>(w);
			}
		}
		if (sim.wall_of_beam[i] < 0)
		{
			scan.setScanRange(i, scan.maxRange);
			scan.setScanRangeValidity(i, false);
			continue;
		}
		sim.true_range_m[i] = best;
		const double sigma = walls[static_cast<size_t>(sim.wall_of_beam[i])].noise_sigma_m;
		const double noisy = sigma > 0 ? best + std::normal_distribution<double>(0, sigma)(rng) : best;
		scan.setScanRange(i, static_cast<float>(noisy));
		scan.setScanRangeValidity(i, noisy > 0 && noisy < layout.max_range_m);
	}
	return sim;
}

std::vector<TVisibleWall> visibleWalls(const TSyntheticScan& sim, size_t min_beams, double min_length_m)
{
	std::vector<TVisibleWall> out;
	auto hitPoint = [&](size_t i) {
		const double a = sim.scan.getScanAngle(i), r = sim.true_range_m[i];
		return mrpt::math::TPoint2D(r * std::cos(a), r * std::sin(a));
	};
	const size_t n = sim.wall_of_beam.size();
	for (size_t i = 0; i < n;)
	{
		const int w = sim.wall_of_beam[i];
		size_t j = i;
		while (j + 1 < n && sim.wall_of_beam[j + 1] == w) ++j;
		if (w >= 0 && j - i + 1 >= min_beams)
		{
			TVisibleWall v;
			v.wall = static_cast<size_t>(w);
			v.first_beam = i;
			v.last_beam = j;
			v.p0 = hitPoint(i);
			v.p1 = hitPoint(j);
			if (v.length_m() >= min_length_m) out.push_back(v);
		}
		i = j + 1;
	}
	return out;
}

}  // namespace hslam::benchdata
