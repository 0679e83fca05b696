/* hslam sim: CSimRobot2NavInterface (see CSimRobot2NavInterface.h). */
#include <hslam/sim/CSimRobot2NavInterface.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace hslam::sim
{
CSimRobot2NavInterface::CSimRobot2NavInterface(double clockOrigin_s, bool compensateScanAge, bool useSonar)
	: m_clockOrigin_s(clockOrigin_s), m_compensate(compensateScanAge), m_useSonar(useSonar)
{
}

void CSimRobot2NavInterface::setInput(const TControlInput& in)
{
	const double dt = in.t_s - m_t_s;
	if (m_havePose && dt > 1e-6)
	{
		m_velGlobal.vx = (in.pose.x - m_pose.x) / dt;
		m_velGlobal.vy = (in.pose.y - m_pose.y) / dt;
		m_velGlobal.omega = mrpt::math::wrapToPi(in.pose.phi - m_pose.phi) / dt;
	}
	m_pose = in.pose;
	m_havePose = true;
	m_history.emplace_back(in.t_s, in.pose);
	while (m_history.size() > 2 && m_history.front().first < in.t_s - 2.0) m_history.pop_front();
	m_t_s = in.t_s;
	m_scan = in.scan;
	m_sonar = in.sonar;
}

mrpt::system::TTimeStamp CSimRobot2NavInterface::stamp(double t_s) const
{
	return mrpt::Clock::fromDouble(m_clockOrigin_s + t_s);
}

mrpt::math::TPose2D CSimRobot2NavInterface::poseAt(double t_s) const
{
	if (m_history.empty()) return m_pose;
	if (t_s <= m_history.front().first) return m_history.front().second;
	for (size_t i = 1; i < m_history.size(); ++i)
	{
		const auto& [t0, a] = m_history[i - 1];
		const auto& [t1, b] = m_history[i];
		if (t_s > t1) continue;
		const double f = t1 > t0 ? (t_s - t0) / (t1 - t0) : 1.0;
		return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.phi + f * mrpt::math::wrapToPi(b.phi - a.phi)};
	}
	return m_history.back().second;
}

bool CSimRobot2NavInterface::getCurrentPoseAndSpeeds(mrpt::math::TPose2D& pose, mrpt::math::TTwist2D& velGlobal,
													 mrpt::system::TTimeStamp& timestamp,
													 mrpt::math::TPose2D& odometry, std::string& frameId)
{
	if (!m_havePose) return false;
	pose = m_pose;
	odometry = m_pose;  // the closed loop's pose (true pose: a localised robot)
	velGlobal = m_velGlobal;
	timestamp = stamp(m_t_s);
	frameId = "map";
	return true;
}

bool CSimRobot2NavInterface::changeSpeeds(const mrpt::kinematics::CVehicleVelCmd& cmd)
{
	const auto* dd = dynamic_cast<const mrpt::kinematics::CVehicleVelCmd_DiffDriven*>(&cmd);
	if (!dd) return false;  // a PTG for another kinematics: not a P3-DX command
	m_v = dd->lin_vel;
	m_w = dd->ang_vel;
	return true;
}

bool CSimRobot2NavInterface::stop(bool)
{
	m_v = m_w = 0;
	return true;
}

mrpt::kinematics::CVehicleVelCmd::Ptr CSimRobot2NavInterface::getStopCmd()
{
	auto cmd = std::make_shared<mrpt::kinematics::CVehicleVelCmd_DiffDriven>();
	cmd->setToStop();
	return cmd;
}

mrpt::poses::CPose2D CSimRobot2NavInterface::nowFromThen(mrpt::system::TTimeStamp stamp) const
{
	if (!m_compensate) return {};
	const double then_s = mrpt::Clock::toDouble(stamp) - m_clockOrigin_s;
	return mrpt::poses::CPose2D(poseAt(then_s)) - mrpt::poses::CPose2D(m_pose);
}

void CSimRobot2NavInterface::addSonarEchoes(mrpt::maps::CSimplePointsMap& obstacles) const
{
	const auto frame = nowFromThen(m_sonar->timestamp);
	for (const auto& m : m_sonar->sensedData)
	{
		if (!(m.sensedDistance > 0) || m.sensedDistance >= m_sonar->maxSensorDistance - 1e-3) continue;  // no echo
		const auto& sp = m.sensorPose;
		const mrpt::math::TPoint2D inSensor(sp.x + m.sensedDistance * std::cos(sp.yaw),
											sp.y + m.sensedDistance * std::sin(sp.yaw));
		const auto p = frame.composePoint(inSensor);
		obstacles.insertPoint(p.x, p.y, 0.0);
	}
}

bool CSimRobot2NavInterface::senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
											mrpt::system::TTimeStamp& timestamp)
{
	obstacles.clear();
	timestamp = stamp(m_t_s);
	if (m_scan)
	{
		// The scan's points through its sensor pose, in the robot frame now (or then).
		obstacles.insertObservation(*m_scan, mrpt::poses::CPose3D(nowFromThen(m_scan->timestamp)));
		if (!m_compensate) timestamp = m_scan->timestamp;
	}
	if (m_useSonar && m_sonar) addSonarEchoes(obstacles);
	return true;
}
}  // namespace hslam::sim
