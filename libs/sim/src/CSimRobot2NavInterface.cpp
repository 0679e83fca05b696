/* hslam sim: CSimRobot2NavInterface (see CSimRobot2NavInterface.h). */
#include <hslam/sim/CSimRobot2NavInterface.h>
#include <mrpt/core/Clock.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

namespace hslam::sim
{
CSimRobot2NavInterface::CSimRobot2NavInterface(double clockOrigin_s) : m_clockOrigin_s(clockOrigin_s) {}

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
	m_t_s = in.t_s;
	m_scan = in.scan;
}

mrpt::system::TTimeStamp CSimRobot2NavInterface::stamp(double t_s) const
{
	return mrpt::Clock::fromDouble(m_clockOrigin_s + t_s);
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

bool CSimRobot2NavInterface::senseObstacles(mrpt::maps::CSimplePointsMap& obstacles,
											mrpt::system::TTimeStamp& timestamp)
{
	obstacles.clear();
	timestamp = stamp(m_t_s);
	if (!m_scan) return true;  // nothing seen yet: no obstacles
	obstacles.insertObservation(*m_scan);  // robot frame: the map sits at the robot's origin
	timestamp = m_scan->timestamp;
	return true;
}
}  // namespace hslam::sim
