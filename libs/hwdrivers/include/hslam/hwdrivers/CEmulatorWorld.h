/* hslam: the world seen by the device emulators (Pioneer sonars, LMS200 laser).
 *
 * Pluggable: emulators only need the range along a ray. CBoxWorld is an
 * axis-aligned rectangular room with optional rectangular obstacles, ray-cast
 * exactly (so tests can derive expected ranges by hand); the simulator's world
 * (issue 4, branch sim) plugs in through the same interface. */
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::hwdrivers
{
class CEmulatorWorld
{
   public:
	virtual ~CEmulatorWorld() = default;
	/** Distance (m) from (x, y) along angle_rad to the first obstacle, or
	 * maxRange_m if nothing is hit within it. */
	virtual double rayRange_m(double x, double y, double angle_rad, double maxRange_m) const = 0;
};

class CBoxWorld : public CEmulatorWorld
{
   public:
	struct TBox
	{
		double xmin, ymin, xmax, ymax;
	};
	/** A room whose walls are the border of `room`, plus solid `obstacles`. */
	explicit CBoxWorld(const TBox& room, std::vector<TBox> obstacles = {}) : m_room(room), m_obstacles(std::move(obstacles))
	{
	}
	double rayRange_m(double x, double y, double angle_rad, double maxRange_m) const override;

   private:
	TBox m_room;
	std::vector<TBox> m_obstacles;
};

/** The emulated robot's motion: true pose and the odometry its encoders
 * report. Pluggable like the world (the simulator's CDiffDriveRobot with its
 * UMBmark errors plugs in through hslam-device-emulator). */
class CEmulatorKinematics
{
   public:
	virtual ~CEmulatorKinematics() = default;
	/** Advances dt_s with the commanded velocities. */
	virtual void step(double v_mps, double w_rad_s, double dt_s) = 0;
	virtual mrpt::poses::CPose2D truePose() const = 0;
	/** Dead-reckoning pose (any fixed origin). */
	virtual mrpt::poses::CPose2D odometryPose() const = 0;
};

/** Error-free differential drive: exact arc integration, odometry = truth. */
class CExactKinematics : public CEmulatorKinematics
{
   public:
	explicit CExactKinematics(const mrpt::poses::CPose2D& start) : m_pose(start) {}
	void step(double v_mps, double w_rad_s, double dt_s) override;
	mrpt::poses::CPose2D truePose() const override { return m_pose; }
	mrpt::poses::CPose2D odometryPose() const override { return m_pose; }

   private:
	mrpt::poses::CPose2D m_pose;
};

}  // namespace hslam::hwdrivers
