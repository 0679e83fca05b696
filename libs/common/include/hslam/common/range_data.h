/* hslam: one range-data record per laser scan, built once by the pipeline and
 * handed to every stage (line extraction, scan matching, dynamic objects,
 * grid insertion), like Cartographer's RangeData: beams with bearing, range
 * and validity, and the valid returns as points in the robot frame.
 *
 * One rule decides whether a beam is a return (isValidReturn): MRPT's
 * validity flag is set, the range is finite, > 0 and below the scanner's
 * maxRange (a return at maxRange is the "no echo" value). Stages that use
 * fewer beams (a maximum range of their own, a mask of people) filter the
 * record; they never re-derive the geometry. Bearings come from MRPT's own
 * scan geometry (CObservation2DRangeScan::getScanAngle), so a right-to-left
 * or left-to-right scanner and any aperture are handled in one place. They
 * are computed in double precision (MRPT's CSinCosLookUpTableFor2DScans is
 * float: ~1e-7 relative error, and 181 cos/sin per scan cost ~3 us). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace hslam::common
{
/** Where a 2D scanner's beams lie on the robot's plane, from the scan's full
 * 3D sensorPose. The beam at scan angle a points along bearing yaw_rad + a,
 * or yaw_rad - a when the scanner is mounted upside down (its z axis points
 * down: a roll of 180 deg, as rawlog-grabber's pose_roll = 180 records it;
 * its beams then sweep clockwise seen from above). The 2D part of the pose
 * alone (CPose2D(sensorPose)) reads such a scanner's scans as the world
 * mirrored. Tilts of a few degrees are ignored: the maps are of one plane. */
struct TScanMount
{
	double x_m = 0, y_m = 0;
	double yaw_rad = 0;  //!< bearing (robot frame) of the beam at scan angle 0
	bool upside_down = false;

	/** Robot-frame bearing of the beam at `scanAngle_rad`. */
	double bearing(double scanAngle_rad) const { return yaw_rad + (upside_down ? -scanAngle_rad : scanAngle_rad); }
	/** (x, y, yaw_rad): composed with a point (r cos a, sineSign() x r sin a). */
	mrpt::poses::CPose2D pose() const { return {x_m, y_m, yaw_rad}; }
	/** -1 for an upside-down scanner: the sign of a beam's sine in pose(). */
	double sineSign() const { return upside_down ? -1.0 : 1.0; }
};

/** The mount of a scanner at `sensorPose` (robot frame). */
TScanMount scanMount(const mrpt::poses::CPose3D& sensorPose);

/** The robot's outline in its own frame (x forward, y left): a return
 * inside it is the robot itself (a mast, a bumper, cables) or a sensor
 * fault, never the world. All zero = no outline. */
struct TRobotFootprint
{
	double front_m = 0, rear_m = 0, half_width_m = 0;  //!< x in [-rear, front], |y| <= half_width

	bool empty() const { return front_m + rear_m <= 0 || half_width_m <= 0; }
	bool contains(double x_m, double y_m) const
	{
		return !empty() && x_m <= front_m && x_m >= -rear_m && std::abs(y_m) <= half_width_m;
	}
};

/** Marks the valid returns of `scan` that fall inside `footprint` invalid
 * (the scan's mount applied, scanMount); returns how many. */
size_t invalidateReturnsInside(mrpt::obs::CObservation2DRangeScan& scan, const TRobotFootprint& footprint);
/** Whether some valid return of `scan` falls inside `footprint`. */
bool hasReturnsInside(const mrpt::obs::CObservation2DRangeScan& scan, const TRobotFootprint& footprint);

/** The valid returns of a scan as points in the robot frame, in beam order. */
struct TScanPoints
{
	std::vector<mrpt::math::TPoint2D> xy;  //!< robot frame (m), in beam order
	std::vector<double> range_m;  //!< the measured range of each point
	std::vector<size_t> beam;  //!< index of each point's beam in the scan
	double beam_step_rad = M_PI / 180;  //!< angle between neighbouring beams (aperture / (n - 1))

	size_t size() const { return xy.size(); }
};

struct TRangeData
{
	static constexpr size_t kNoPoint = std::numeric_limits<size_t>::max();

	double t_s = 0;  //!< time stamp of the scan (s)
	/** Sensor on the robot: position, and the bearing of its beam at scan
	 * angle 0 (TScanMount::pose(); for a level scanner the 2D part of the
	 * scan's sensorPose). Use bearing_rad for the beams. */
	mrpt::poses::CPose2D sensor_pose;
	double max_range_m = 0;  //!< the scanner's "no echo" range
	/** Per beam, in scan order: bearing in the robot frame (the mount
	 * included, TScanMount::bearing), measured range (as recorded, also for invalid beams),
	 * direction cosines in the robot frame, and the one validity rule. */
	std::vector<double> bearing_rad, range_m, cos_bearing, sin_bearing;
	std::vector<bool> valid;
	/** Valid returns as points (robot frame); beam_point[b] is the index of
	 * beam b's point, or kNoPoint. */
	TScanPoints points;
	std::vector<size_t> beam_point;

	size_t beamCount() const { return range_m.size(); }
	/** Point at `range` along beam b, robot frame (also for invalid beams). */
	mrpt::math::TPoint2D alongBeam(size_t b, double range) const
	{
		return {sensor_pose.x() + range * cos_bearing[b], sensor_pose.y() + range * sin_bearing[b]};
	}
	/** The valid points in the world frame for the robot at `robotPose`. */
	std::vector<mrpt::math::TPoint2D> worldPoints(const mrpt::poses::CPose2D& robotPose) const;
};

/** The one rule for a usable return (see file comment). */
bool isValidReturn(const mrpt::obs::CObservation2DRangeScan& scan, size_t beam);

/** The record of `scan` (built once per scan by the pipeline). */
TRangeData makeRangeData(const mrpt::obs::CObservation2DRangeScan& scan);

/** A copy of `data` in which the beams flagged in `excluded` (people, for
 * the matchers) are invalid and have no point; `excluded` may be shorter. */
TRangeData withoutBeams(const TRangeData& data, const std::vector<bool>& excluded);

}  // namespace hslam::common
