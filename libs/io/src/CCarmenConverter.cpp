/* hslam io (internal): CCarmenConverter, CARMEN messages -> observations. */
#include "CCarmenConverter.h"

#include <hslam/io/carmen_observations.h>

#include <algorithm>
#include <stdexcept>

namespace hslam::io
{
namespace
{
/** Poses an anchoring ODOM may repeat: the reference pose first. */
std::vector<mrpt::math::TPose2D> posesOf(const TCarmenLaser& laser)
{
	std::vector<mrpt::math::TPose2D> poses;
	if (laser.laserPose) poses.push_back(*laser.laserPose);
	if (laser.robotPose) poses.push_back(*laser.robotPose);
	return poses;
}

/** FLASER: "x y theta"; ROBOTLASER: robot_pose. */
mrpt::math::TPose2D referencePoseOf(const TCarmenLaser& laser)
{
	if (laser.config && laser.robotPose) return *laser.robotPose;
	return *laser.laserPose;
}
}  // namespace

CCarmenConverter::CCarmenConverter(const TCarmenClock& clock, const TCarmenRangeLimits& limits,
								   const TCarmenLaserMounts& mounts, detail::CCarmenRawlogSink& sink)
	: m_clock(clock), m_limits(limits), m_mounts(mounts), m_sink(sink)
{
}

void CCarmenConverter::add(const TCarmenLogEntry& entry)
{
	if (const auto* odo = std::get_if<TCarmenOdometry>(&entry.message))
		m_tracker.addOdometry(odo->pose, odo->tv_mps, odo->rv_radps);
	else if (const auto* laser = std::get_if<TCarmenLaser>(&entry.message))
		addLaser(*laser, entry.line);
}

void CCarmenConverter::addLaser(const TCarmenLaser& laser, size_t line)
{
	if (m_scanIndex >= m_clock.t_s.size()) throw std::logic_error("CCarmenConverter: more scans than clock entries");
	const double t_s = m_clock.t_s[m_scanIndex++];
	switch (laser.role)
	{
		case TCarmenLaserRole::lrFront:
			addFrontScan(laser, line, t_s);
			++m_front;
			return;
		case TCarmenLaserRole::lrRear:
			m_tracker.addRearScan(posesOf(laser));
			writeScan(laser, t_s);
			++m_rear;
			return;
		case TCarmenLaserRole::lrRaw:
			writeScan(laser, t_s);
			++m_raw;
			return;
	}
}

void CCarmenConverter::addFrontScan(const TCarmenLaser& laser, size_t line, double t_s)
{
	const TCarmenOdometryStep step = m_tracker.addFrontScan(posesOf(laser));
	writeOdometryOrGap(step, line, t_s);
	writeScan(laser, t_s);
	m_reference.push_back({t_s, referencePoseOf(laser)});
	m_previousFrontLine = line;
}

void CCarmenConverter::writeOdometryOrGap(const TCarmenOdometryStep& step, size_t line, double t_s)
{
	if (step.first || step.incrementKnown)
	{
		m_sink.odometry(step, t_s);
		++m_odometry;
		return;
	}
	++m_gaps;
	const std::string text = "ODOMETRY_GAP: odometry missing between front scans " + std::to_string(m_front - 1) + " and " +
							 std::to_string(m_front) + " (lines " + std::to_string(m_previousFrontLine) + " and " +
							 std::to_string(line) + "): no ODOMETRY observation for scan " + std::to_string(m_front) +
							 "; do not difference odometry across this gap";
	m_sink.gap(makeComment("ODOMETRY_GAP", text, t_s));
}

void CCarmenConverter::writeScan(const TCarmenLaser& laser, double t_s)
{
	const TCarmenScanGeometry geometry = carmenScanGeometry(laser);
	if (geometry.warning) warnOnce(*geometry.warning);
	const auto sensorPose = carmenSensorPose(laser, m_mounts, geometry);
	m_sink.write(makeCarmenScan(laser, geometry, sensorPose, m_limits, t_s));
}

void CCarmenConverter::warnOnce(const std::string& warning)
{
	if (std::find(m_warnings.begin(), m_warnings.end(), warning) == m_warnings.end()) m_warnings.push_back(warning);
}

void CCarmenConverter::fillReport(TCarmenImportReport& report) const
{
	report.frontScans = m_front;
	report.rearScans = m_rear;
	report.rawScans = m_raw;
	report.odometryObservations = m_odometry;
	report.odometryGaps = m_gaps;
	report.odometryAnchors = m_tracker.anchors();
	report.referencePoses = m_reference.size();
	report.warnings.insert(report.warnings.end(), m_warnings.begin(), m_warnings.end());
}

}  // namespace hslam::io
