/* hslam: CARMEN beam layout and laser mounting to MRPT scan geometry. */
#include <hslam/common/parse_number.h>
#include <hslam/io/carmen_scan_geometry.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <stdexcept>

#include "text_format.h"

namespace hslam::io
{
namespace
{
using mrpt::DEG2RAD;

// CARMEN's reader: first beam of FLASER/RLASER at -90 deg (see header).
const double kCarmenFirstBeam_rad = DEG2RAD(-90.0);

double guessedStep_rad(size_t n) { return n <= 181 ? DEG2RAD(1.0) : DEG2RAD(0.5); }

bool isKnownBeamCount(size_t n) { return n == 180 || n == 181 || n == 360 || n == 361; }

TCarmenScanGeometry fromFirstBeamAndStep(size_t n, double firstBeam_rad, double step_rad)
{
	TCarmenScanGeometry g;
	g.aperture_rad = n > 1 ? static_cast<double>(n - 1) * step_rad : 0.0;
	g.centreYaw_rad = firstBeam_rad + 0.5 * g.aperture_rad;
	return g;
}

TCarmenScanGeometry oldLaserGeometry(const TCarmenLaser& laser)
{
	const size_t n = laser.ranges_m.size();
	auto g = fromFirstBeamAndStep(n, kCarmenFirstBeam_rad, guessedStep_rad(n));
	if (!isKnownBeamCount(n))
		g.warning = laser.name + " with " + std::to_string(n) + " beams: angular step assumed " +
					(n <= 181 ? "1" : "0.5") + " deg from -90 deg";
	return g;
}

TCarmenScanGeometry configuredGeometry(const TCarmenLaser& laser, const TCarmenLaserConfig& cfg)
{
	const size_t n = laser.ranges_m.size();
	if (std::isfinite(cfg.resolution_rad) && cfg.resolution_rad > 0)
		return fromFirstBeamAndStep(n, cfg.startAngle_rad, cfg.resolution_rad);
	auto g = fromFirstBeamAndStep(n, cfg.startAngle_rad, guessedStep_rad(n));
	g.warning = laser.name + " with angular_resolution " + detail::formatNumber(cfg.resolution_rad) +
				": step assumed " + (n <= 181 ? "1" : "0.5") + " deg";
	return g;
}

double paramOrZero(const std::map<std::string, TCarmenParamValue>& params, const std::string& name,
				   const std::string& path)
{
	const auto it = params.find(name);
	if (it == params.end()) return 0.0;
	const auto value = hslam::common::tryParseDouble(it->second.value);
	if (!value)
		throw std::runtime_error(path + ":" + std::to_string(it->second.line) + ": PARAM " + name + " value '" +
								 it->second.value + "' is not a number");
	return *value;
}

TCarmenLaserMount mountFromParams(const std::map<std::string, TCarmenParamValue>& params, const std::string& prefix,
								  double extraYaw_rad, const std::string& path)
{
	TCarmenLaserMount m;
	m.x_m = paramOrZero(params, prefix + "_offset", path);
	m.y_m = paramOrZero(params, prefix + "_side_offset", path);
	m.yaw_rad = paramOrZero(params, prefix + "_angular_offset", path) + extraYaw_rad;
	return m;
}

TCarmenLaserMount mountOf(const TCarmenLaser& laser, const TCarmenLaserMounts& mounts)
{
	const bool hasBothPoses = laser.config && laser.laserPose && laser.robotPose;
	if (hasBothPoses)  // ROBOTLASER: robot_pose^-1 (+) laser_pose
	{
		const auto rel = mrpt::poses::CPose2D(*laser.laserPose) - mrpt::poses::CPose2D(*laser.robotPose);
		return {rel.x(), rel.y(), rel.phi()};
	}
	if (laser.role == TCarmenLaserRole::lrFront) return mounts.front;
	if (laser.role == TCarmenLaserRole::lrRear) return mounts.rear;
	if (laser.rawIndex == 1) return mounts.front;
	if (laser.rawIndex == 2) return mounts.rear;
	return {};
}
}  // namespace

TCarmenScanGeometry carmenScanGeometry(const TCarmenLaser& laser)
{
	return laser.config ? configuredGeometry(laser, *laser.config) : oldLaserGeometry(laser);
}

TCarmenLaserMounts carmenLaserMounts(const std::map<std::string, TCarmenParamValue>& params, const std::string& path)
{
	TCarmenLaserMounts mounts;
	mounts.front = mountFromParams(params, "robot_frontlaser", 0.0, path);
	mounts.rear = mountFromParams(params, "robot_rearlaser", M_PI, path);
	return mounts;
}

mrpt::poses::CPose3D carmenSensorPose(const TCarmenLaser& laser, const TCarmenLaserMounts& mounts,
									  const TCarmenScanGeometry& geometry)
{
	const TCarmenLaserMount m = mountOf(laser, mounts);
	const double yaw_rad = mrpt::math::wrapToPi(m.yaw_rad + geometry.centreYaw_rad);
	return mrpt::poses::CPose3D(m.x_m, m.y_m, 0.0, yaw_rad, 0.0, 0.0);
}

}  // namespace hslam::io
