/* hslam: exact ray casting in a box world (see CEmulatorWorld.h). */
#include <hslam/hwdrivers/CEmulatorWorld.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hslam::hwdrivers
{
namespace
{
/** Slab method: entry/exit distances of a ray through an axis-aligned box. */
bool rayBox(double x, double y, double dx, double dy, const CBoxWorld::TBox& b, double& tIn, double& tOut)
{
	tIn = -std::numeric_limits<double>::infinity();
	tOut = std::numeric_limits<double>::infinity();
	const double o[2] = {x, y}, d[2] = {dx, dy}, lo[2] = {b.xmin, b.ymin}, hi[2] = {b.xmax, b.ymax};
	for (int k = 0; k < 2; ++k)
	{
		if (std::abs(d[k]) < 1e-12)
		{
			if (o[k] < lo[k] || o[k] > hi[k]) return false;
			continue;
		}
		double t1 = (lo[k] - o[k]) / d[k], t2 = (hi[k] - o[k]) / d[k];
		if (t1 > t2) std::swap(t1, t2);
		tIn = std::max(tIn, t1);
		tOut = std::min(tOut, t2);
	}
	return tIn <= tOut;
}
}  // namespace

double CBoxWorld::rayRange_m(double x, double y, double angle_rad, double maxRange_m) const
{
	const double dx = std::cos(angle_rad), dy = std::sin(angle_rad);
	double best = maxRange_m, tIn, tOut;
	// Inside the room the walls are hit where the ray leaves the room box.
	if (rayBox(x, y, dx, dy, m_room, tIn, tOut) && tOut >= 0) best = std::min(best, tOut);
	for (const auto& b : m_obstacles)
		if (rayBox(x, y, dx, dy, b, tIn, tOut) && tOut >= 0) best = std::min(best, std::max(0.0, tIn));
	return best;
}

void CExactKinematics::step(double v, double w, double dt)
{
	const double th = m_pose.phi(), thNew = th + w * dt;
	double x = m_pose.x(), y = m_pose.y();
	if (std::abs(w) < 1e-9)
	{
		x += v * dt * std::cos(th);
		y += v * dt * std::sin(th);
	}
	else
	{
		x += v / w * (std::sin(thNew) - std::sin(th));
		y -= v / w * (std::cos(thNew) - std::cos(th));
	}
	m_pose = mrpt::poses::CPose2D(x, y, std::atan2(std::sin(thNew), std::cos(thNew)));
}

}  // namespace hslam::hwdrivers
