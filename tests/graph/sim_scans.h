/* Test helpers: worlds built in code and laser scans ray-cast in them by
 * libs/sim (exact ground truth), as point clouds for the graph library. */
#pragma once

#include <hslam/graph/CCorrelativeScanMatcher.h>
#include <hslam/sim/CLaserSimulator.h>
#include <hslam/sim/world.h>
#include <mrpt/poses/CPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <random>
#include <vector>

namespace hslam::graph::testing
{
/** Adds the closed polygon through `corners` as walls. */
inline void addPolygon(sim::CWorld& world, const std::vector<mrpt::math::TPoint2D>& corners)
{
	for (size_t i = 0; i < corners.size(); ++i) world.addSegment({corners[i], corners[(i + 1) % corners.size()], {}});
}

inline void addBox(sim::CWorld& world, double x0, double y0, double x1, double y1)
{
	addPolygon(world, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

/** Points (robot frame) of an LMS200 scan (181 beams, 8 m, 1 cm noise) at `truePose`. */
inline TPointCloud2D scanPoints(const sim::CWorld& world, const mrpt::math::TPose2D& truePose, std::mt19937_64& rng)
{
	const sim::CLaserSimulator laser;
	mrpt::obs::CObservation2DRangeScan scan;
	laser.simulate(world, truePose, rng, scan);
	const mrpt::poses::CPose2D sensor(scan.sensorPose.x(), scan.sensorPose.y(), scan.sensorPose.yaw());
	TPointCloud2D points;
	const size_t n = scan.getScanSize();
	for (size_t i = 0; i < n; ++i)
	{
		if (!scan.getScanRangeValidity(i)) continue;
		const double a = -0.5 * scan.aperture + scan.aperture * i / (n - 1), r = scan.getScanRange(i);
		const auto p = sensor + mrpt::poses::CPoint2D(r * std::cos(a), r * std::sin(a));
		points.push_back({static_cast<float>(p.x()), static_cast<float>(p.y())});
	}
	return points;
}

/** Points of `local` (frame `pose`) expressed in the frame of `frame`. */
inline TPointCloud2D transformPoints(const TPointCloud2D& local, const mrpt::math::TPose2D& pose,
									 const mrpt::math::TPose2D& frame = {0, 0, 0})
{
	const auto rel = mrpt::poses::CPose2D(pose) - mrpt::poses::CPose2D(frame);
	TPointCloud2D out;
	for (const auto& p : local)
	{
		double x, y;
		rel.composePoint(p.x, p.y, x, y);
		out.push_back({static_cast<float>(x), static_cast<float>(y)});
	}
	return out;
}

/** An irregular room 10 x 7 m with an alcove and furniture (no symmetry). */
inline sim::CWorld irregularRoom()
{
	sim::CWorld w;
	addPolygon(w, {{0, 0}, {10, 0}, {10, 4}, {8.5, 4}, {8.5, 7}, {0, 7}});
	addBox(w, 2.0, 1.5, 3.0, 2.1);
	addBox(w, 6.0, 5.0, 6.4, 6.2);
	w.addCircle({{4.5, 4.0}, 0.15, {}});
	w.addCircle({{7.2, 1.3}, 0.1, {}});
	return w;
}

}  // namespace hslam::graph::testing
