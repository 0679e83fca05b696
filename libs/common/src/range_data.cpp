/* hslam: the range-data record of a scan (see range_data.h). */
#include <hslam/common/range_data.h>

#include <mrpt/system/datetime.h>

#include <algorithm>
#include <cmath>

namespace hslam::common
{
bool isValidReturn(const mrpt::obs::CObservation2DRangeScan& scan, size_t beam)
{
	if (!scan.getScanRangeValidity(beam)) return false;
	const float r = scan.getScanRange(beam);
	return std::isfinite(r) && r > 0 && r < scan.maxRange;
}

std::vector<mrpt::math::TPoint2D> TRangeData::worldPoints(const mrpt::poses::CPose2D& robotPose) const
{
	std::vector<mrpt::math::TPoint2D> out(points.size());
	for (size_t i = 0; i < points.size(); ++i) robotPose.composePoint(points.xy[i], out[i]);
	return out;
}

TScanMount scanMount(const mrpt::poses::CPose3D& sensorPose)
{
	TScanMount m;
	m.x_m = sensorPose.x(), m.y_m = sensorPose.y();
	const auto R = sensorPose.getRotationMatrix();
	m.upside_down = R(2, 2) < 0;
	// level: the pose's own yaw (exactly what CPose2D(sensorPose) takes);
	// upside down: the direction of the sensor's x axis, which a yaw / pitch
	// / roll triple may spell either as (yaw, 0, 180) or (yaw + 180, 180, 0)
	m.yaw_rad = m.upside_down ? std::atan2(R(1, 0), R(0, 0)) : sensorPose.yaw();
	return m;
}

TRangeData makeRangeData(const mrpt::obs::CObservation2DRangeScan& scan)
{
	TRangeData d;
	const size_t n = scan.getScanSize();
	d.t_s = mrpt::Clock::toDouble(scan.timestamp);
	const TScanMount mount = scanMount(scan.sensorPose);
	d.sensor_pose = mount.pose();
	d.max_range_m = scan.maxRange;
	if (n > 1) d.points.beam_step_rad = scan.aperture / static_cast<double>(n - 1);
	d.bearing_rad.resize(n), d.range_m.resize(n), d.cos_bearing.resize(n), d.sin_bearing.resize(n);
	d.valid.resize(n), d.beam_point.assign(n, TRangeData::kNoPoint);
	d.points.xy.reserve(n), d.points.range_m.reserve(n), d.points.beam.reserve(n);
	for (size_t b = 0; b < n; ++b)
	{
		const double a = scan.getScanAngle(b);  // sensor frame
		d.bearing_rad[b] = mount.bearing(a);
		d.cos_bearing[b] = std::cos(d.bearing_rad[b]);
		d.sin_bearing[b] = std::sin(d.bearing_rad[b]);
		d.range_m[b] = scan.getScanRange(b);
		d.valid[b] = isValidReturn(scan, b);
		if (!d.valid[b]) continue;
		const double r = d.range_m[b];
		mrpt::math::TPoint2D p;
		d.sensor_pose.composePoint(r * std::cos(a), mount.sineSign() * r * std::sin(a), p.x, p.y);
		d.beam_point[b] = d.points.xy.size();
		d.points.xy.push_back(p);
		d.points.range_m.push_back(r);
		d.points.beam.push_back(b);
	}
	return d;
}

namespace
{
/** Calls f(beam) for each valid return of `scan` inside `footprint`. */
template <class F>
void forReturnsInside(const mrpt::obs::CObservation2DRangeScan& scan, const TRobotFootprint& footprint, F f)
{
	if (footprint.empty()) return;
	const TScanMount mount = scanMount(scan.sensorPose);
	const mrpt::poses::CPose2D sensor = mount.pose();
	// no return farther from the sensor than the outline's farthest corner is inside
	const double reach_m = std::hypot(std::max(footprint.front_m - mount.x_m, footprint.rear_m + mount.x_m),
									  footprint.half_width_m + std::abs(mount.y_m));
	for (size_t b = 0; b < scan.getScanSize(); ++b)
	{
		if (!isValidReturn(scan, b) || scan.getScanRange(b) > reach_m) continue;
		const double r = scan.getScanRange(b), a = scan.getScanAngle(b);
		double x = 0, y = 0;
		sensor.composePoint(r * std::cos(a), mount.sineSign() * r * std::sin(a), x, y);
		if (footprint.contains(x, y) && f(b)) return;
	}
}
}  // namespace

size_t invalidateReturnsInside(mrpt::obs::CObservation2DRangeScan& scan, const TRobotFootprint& footprint)
{
	size_t n = 0;
	forReturnsInside(scan, footprint, [&](size_t b) {
		scan.setScanRangeValidity(b, false);
		++n;
		return false;  // all of them
	});
	return n;
}

bool hasReturnsInside(const mrpt::obs::CObservation2DRangeScan& scan, const TRobotFootprint& footprint)
{
	bool any = false;
	forReturnsInside(scan, footprint, [&](size_t) { return any = true; });
	return any;
}

TRangeData withoutBeams(const TRangeData& data, const std::vector<bool>& excluded)
{
	TRangeData d = data;
	d.points.xy.clear(), d.points.range_m.clear(), d.points.beam.clear();
	for (size_t b = 0; b < d.beamCount(); ++b)
	{
		if (b < excluded.size() && excluded[b]) d.valid[b] = false;
		if (!d.valid[b])
		{
			d.beam_point[b] = TRangeData::kNoPoint;
			continue;
		}
		const size_t i = data.beam_point[b];
		d.beam_point[b] = d.points.xy.size();
		d.points.xy.push_back(data.points.xy[i]);
		d.points.range_m.push_back(data.points.range_m[i]);
		d.points.beam.push_back(b);
	}
	return d;
}

}  // namespace hslam::common
