/* hslam: building MRPT observations from CARMEN messages. */
#include <hslam/io/carmen_observations.h>

#include <algorithm>

#include <mrpt/core/Clock.h>

namespace hslam::io
{
std::string carmenScanLabel(const TCarmenLaser& laser)
{
	switch (laser.role)
	{
		case TCarmenLaserRole::lrFront:
			return "LASER";
		case TCarmenLaserRole::lrRear:
			return "REAR_LASER";
		case TCarmenLaserRole::lrRaw:
			break;
	}
	return laser.rawIndex <= 1 ? "LASER" : "LASER" + std::to_string(laser.rawIndex);
}

mrpt::obs::CObservation2DRangeScan::Ptr makeCarmenScan(const TCarmenLaser& laser, const TCarmenScanGeometry& geometry,
													   const mrpt::poses::CPose3D& sensorPose,
													   const TCarmenRangeLimits& limits, double t_s)
{
	auto scan = mrpt::obs::CObservation2DRangeScan::Create();
	scan->sensorLabel = carmenScanLabel(laser);
	scan->timestamp = mrpt::Clock::fromDouble(t_s);
	scan->aperture = static_cast<float>(geometry.aperture_rad);
	scan->rightToLeft = true;  // CARMEN beams go counter-clockwise
	scan->maxRange = static_cast<float>(limits.maxRange_m);
	scan->stdError = kCarmenRangeStdError_m;
	scan->sensorPose = sensorPose;
	scan->resizeScan(laser.ranges_m.size());
	for (size_t i = 0; i < laser.ranges_m.size(); ++i)
	{
		// An invalid beam's value is clamped into float range (a 1e308 outlier
		// would overflow the float conversion).
		const double r_m = laser.ranges_m[i];
		const bool valid = limits.isValid(r_m);
		scan->setScanRange(i, static_cast<float>(valid ? r_m : std::clamp(r_m, 0.0, std::max(limits.maxRange_m, 0.0))));
		scan->setScanRangeValidity(i, valid);
	}
	return scan;
}

mrpt::obs::CObservationOdometry::Ptr makeCarmenOdometry(const TCarmenOdometryStep& step, double t_s)
{
	auto odo = mrpt::obs::CObservationOdometry::Create();
	odo->sensorLabel = "ODOMETRY";
	odo->timestamp = mrpt::Clock::fromDouble(t_s);
	odo->odometry = step.chainPose;
	odo->hasVelocities = step.hasVelocities;
	odo->velocityLocal = mrpt::math::TTwist2D(step.tv_mps, 0.0, step.rv_radps);
	return odo;
}

mrpt::obs::CObservationComment::Ptr makeComment(const std::string& label, const std::string& text, double t_s)
{
	auto comment = mrpt::obs::CObservationComment::Create();
	comment->sensorLabel = label;
	comment->timestamp = mrpt::Clock::fromDouble(t_s);
	comment->text = text;
	return comment;
}

}  // namespace hslam::io
