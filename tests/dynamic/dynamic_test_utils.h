/* Synthetic laser scans for the dynamic object tests: exact ray casting
 * against circles (legs, posts) and wall segments, seen from a robot pose. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <vector>

namespace hslam::dynamic::testutils
{
struct TCircle
{
	double x, y, r;
};
struct TWall
{
	double x0, y0, x1, y1;
};

inline double rayCircle(double ox, double oy, double dx, double dy, const TCircle& c)
{
	const double fx = ox - c.x, fy = oy - c.y;
	const double b = fx * dx + fy * dy, cc = fx * fx + fy * fy - c.r * c.r, disc = b * b - cc;
	if (disc < 0) return INFINITY;
	const double t = -b - std::sqrt(disc);
	return t > 0 ? t : INFINITY;
}

inline double rayWall(double ox, double oy, double dx, double dy, const TWall& w)
{
	const double ex = w.x1 - w.x0, ey = w.y1 - w.y0, den = dx * ey - dy * ex;
	if (std::abs(den) < 1e-12) return INFINITY;
	const double t = ((w.x0 - ox) * ey - (w.y0 - oy) * ex) / den, u = ((w.x0 - ox) * dy - (w.y0 - oy) * dx) / den;
	return (t > 0 && u >= 0 && u <= 1) ? t : INFINITY;
}

/** Scan of `beams` beams over `aperture_rad` (MRPT convention, right to
 * left, centred on the sensor x axis), sensor at the robot origin. */
inline mrpt::obs::CObservation2DRangeScan castScan(const mrpt::poses::CPose2D& robot, const std::vector<TCircle>& circles,
												   const std::vector<TWall>& walls, size_t beams = 181,
												   double aperture_rad = M_PI, double maxRange_m = 8.0)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(aperture_rad);
	scan.rightToLeft = true;
	scan.maxRange = static_cast<float>(maxRange_m);
	scan.resizeScan(beams);
	for (size_t i = 0; i < beams; ++i)
	{
		const double a = robot.phi() - 0.5 * aperture_rad + aperture_rad * static_cast<double>(i) / (beams - 1);
		const double dx = std::cos(a), dy = std::sin(a);
		double r = INFINITY;
		for (const auto& c : circles) r = std::min(r, rayCircle(robot.x(), robot.y(), dx, dy, c));
		for (const auto& w : walls) r = std::min(r, rayWall(robot.x(), robot.y(), dx, dy, w));
		const bool valid = r < maxRange_m;
		scan.setScanRange(i, static_cast<float>(valid ? r : maxRange_m));
		scan.setScanRangeValidity(i, valid);
	}
	return scan;
}

/** A square room of half side `h` around the origin. */
inline std::vector<TWall> room(double h)
{
	return {{-h, -h, h, -h}, {h, -h, h, h}, {h, h, -h, h}, {-h, h, -h, -h}};
}

}  // namespace hslam::dynamic::testutils
