/* hslam: the world seen by the device emulators (Pioneer sonars, LMS200 laser).
 *
 * Pluggable: emulators only need the range along a ray. CBoxWorld is an
 * axis-aligned rectangular room with optional rectangular obstacles, ray-cast
 * exactly (so tests can derive expected ranges by hand); the simulator's world
 * (issue 4, branch sim) plugs in through the same interface. */
#pragma once

#include <mrpt/math/TPose2D.h>

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

}  // namespace hslam::hwdrivers
