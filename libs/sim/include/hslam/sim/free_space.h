/* hslam sim: the free space of a world as a grid: cells whose centre has at
 * least `clearance_m` to every static obstacle AND that are connected to a
 * seed point known to be free (so the inside of a box or a closed block, far
 * from every wall but unreachable, is not free). Used to draw start/target
 * pairs and to measure the shortest collision-free path (8-connected
 * Dijkstra) that a navigation run is compared with. */
#pragma once

#include <hslam/sim/world.h>

#include <vector>

namespace hslam::sim
{
class CFreeSpaceGrid
{
   public:
	CFreeSpaceGrid(const CWorld& world, const mrpt::math::TPoint2D& seed, double clearance_m, double cell_m = 0.1);

	bool isFree(const mrpt::math::TPoint2D& p) const;
	/** Centres of all free cells. */
	std::vector<mrpt::math::TPoint2D> freeCells() const;
	/** Length (m) of the shortest 8-connected path through free cells between
	 * the cells of a and b (their own cells count as free); NaN if none. */
	double shortestPath_m(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b) const;

   private:
	int index(const mrpt::math::TPoint2D& p) const;
	mrpt::math::TPoint2D centre(int idx) const;
	double m_x0 = 0, m_y0 = 0, m_cell = 0.1;
	int m_w = 0, m_h = 0;
	std::vector<char> m_free;
};
}  // namespace hslam::sim
