/* hslam: valid scan points in the robot frame (see scan_points.h). */
#include <hslam/features/scan_points.h>

#include <mrpt/poses/CPose2D.h>

#include <cmath>

namespace hslam::features
{
bool isValidBeam(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	if (!scan.getScanRangeValidity(i)) return false;
	const float r = scan.getScanRange(i);
	return std::isfinite(r) && r > 0 && r < scan.maxRange;
}

TScanPoints validScanPoints(const mrpt::obs::CObservation2DRangeScan& scan)
{
	const mrpt::poses::CPose2D sensor(scan.sensorPose);
	TScanPoints out;
	const size_t n = scan.getScanSize();
	out.xy.reserve(n);
	out.range_m.reserve(n);
	out.beam.reserve(n);
	for (size_t i = 0; i < n; ++i)
	{
		if (!isValidBeam(scan, i)) continue;
		const double r = scan.getScanRange(i), a = scan.getScanAngle(i);
		double x = 0, y = 0;
		sensor.composePoint(r * std::cos(a), r * std::sin(a), x, y);
		out.xy.emplace_back(x, y);
		out.range_m.push_back(r);
		out.beam.push_back(i);
	}
	return out;
}

std::vector<TIndexRange> consecutiveBeamRuns(const TScanPoints& points)
{
	std::vector<TIndexRange> runs;
	for (size_t i = 0; i < points.size(); ++i)
	{
		if (runs.empty() || points.beam[i] != points.beam[i - 1] + 1) runs.push_back({i, i});
		runs.back().end = i + 1;
	}
	return runs;
}

}  // namespace hslam::features
