#include <hslam/sim/CPinholeCameraSimulator.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <map>
#include <opencv2/core.hpp>

#include "camera_textures.h"

namespace hslam::sim
{
namespace
{
using mrpt::math::TPoint2D;

enum class ESurface
{
	wall,
	floor,
	ceiling,
	person,
	none
};

struct TSample
{
	double grey = 0;
	ESurface surface = ESurface::none;
	double lambda = 0;  //!< ray parameter of the hit: the depth (camera z) for a ray with camera z = 1
};

/** The two horizontal hits of one ray direction (cached along a column). */
struct THorizontal
{
	double angle_rad = 1e9;
	TRayHit wall, person;
};

/** One cylinder per walking person, around the mean of its legs (tag group = person id). */
CWorld peopleWorld(const CWorld& world, double radius_m)
{
	std::map<int, std::pair<TPoint2D, int>> legs;
	for (const auto& c : world.dynamicCircles())
	{
		if (c.tag.kind != EObjectKind::person_leg) continue;
		auto& [sum, n] = legs[c.tag.group];
		sum.x += c.centre.x;
		sum.y += c.centre.y;
		++n;
	}
	CWorld people;
	for (const auto& [id, acc] : legs)
		people.addCircle(TCircle{{acc.first.x / acc.second, acc.first.y / acc.second}, radius_m,
								 TObjectTag{EObjectKind::person_leg, id, 0}});
	return people;
}

/** Texture coordinate along a flat surface and a key for its line. */
double wallShade(const TRayHit& hit, double z_m)
{
	if (hit.tag.kind == EObjectKind::furniture)
		return textures::wallGrey(0.2 * std::atan2(hit.normal.y, hit.normal.x), z_m, 1000 + hit.tag.group);
	double nx = hit.normal.x, ny = hit.normal.y;
	if (nx < -1e-9 || (std::abs(nx) <= 1e-9 && ny < 0)) nx = -nx, ny = -ny;  // one normal per line, whichever side
	const double offset = hit.point.x * nx + hit.point.y * ny, along = -hit.point.x * ny + hit.point.y * nx;
	const int64_t key = std::llround(offset * 20.0) * 7919 + std::llround(std::atan2(ny, nx) * 100.0);
	const double lambert = 0.65 + 0.35 * std::cos(hit.incidence_rad);
	return lambert * textures::wallGrey(along, z_m, key);
}
}  // namespace

CPinholeCameraSimulator::CPinholeCameraSimulator(TCameraSimOptions options)
	: m_options(std::move(options)), m_camera(vision::mountedCamera(m_options.intrinsics, m_options.mount))
{
}

namespace
{
struct TRenderContext
{
	const CWorld& walls;
	const CWorld& people;
	const TCameraSimOptions& o;
	TPoint2D origin;
	double z0_m;
};

TSample shade(const TRenderContext& c, const double d[3], THorizontal& h)
{
	const double hlen = std::hypot(d[0], d[1]);
	double lambdaVertical = 1e18;  // ray parameter where it meets the floor or the ceiling
	if (d[2] < 0) lambdaVertical = -c.z0_m / d[2];
	if (d[2] > 0) lambdaVertical = (c.o.wall_height_m - c.z0_m) / d[2];
	if (hlen > 1e-12)
	{
		const double angle = std::atan2(d[1], d[0]);
		if (std::abs(angle - h.angle_rad) > 1e-9)
		{
			h.angle_rad = angle;
			h.wall = c.walls.castRay(c.origin, angle, c.o.max_range_m, false);
			h.person = c.people.castRay(c.origin, angle, c.o.max_range_m, false);
		}
		if (h.person.hit && h.person.range_m / hlen < lambdaVertical)
		{
			const double z = c.z0_m + h.person.range_m / hlen * d[2];
			if (z >= 0 && z <= c.o.person_height_m && (!h.wall.hit || h.person.range_m < h.wall.range_m))
				return {textures::personGrey(std::atan2(h.person.normal.y, h.person.normal.x), z, h.person.tag.group),
						ESurface::person, h.person.range_m / hlen};
		}
		if (h.wall.hit && h.wall.range_m / hlen < lambdaVertical)
			return {wallShade(h.wall, c.z0_m + h.wall.range_m / hlen * d[2]), ESurface::wall, h.wall.range_m / hlen};
	}
	if (d[2] == 0) return {100.0, ESurface::none, 0.0};
	const double x = c.origin.x + lambdaVertical * d[0], y = c.origin.y + lambdaVertical * d[1];
	if (d[2] < 0) return {textures::floorGrey(x, y, 3), ESurface::floor, lambdaVertical};
	return {0.7 * textures::floorGrey(x, y, 4) + 80.0, ESurface::ceiling, lambdaVertical};
}

/** BGR tint of a surface for colour images. */
cv::Vec3d tintOf(ESurface s)
{
	switch (s)
	{
		case ESurface::wall: return {0.80, 0.92, 1.00};
		case ESurface::floor: return {1.00, 0.85, 0.75};
		case ESurface::person: return {0.55, 0.70, 1.00};
		default: return {1.0, 1.0, 1.0};
	}
}
}  // namespace

mrpt::obs::CObservation::Ptr CPinholeCameraSimulator::render(const CWorld& world, const mrpt::math::TPose2D& robot,
															 std::mt19937_64& rng) const
{
	const auto& in = m_camera.intrinsics;
	const mrpt::poses::CPose3D cam = mrpt::poses::CPose3D(robot.x, robot.y, 0, robot.phi, 0, 0) + m_camera.sensorPose;
	const auto R = cam.getRotationMatrix();
	const CWorld people = peopleWorld(world, m_options.person_radius_m);
	const TRenderContext ctx{world, people, m_options, TPoint2D{cam.x(), cam.y()}, cam.z()};
	const int W = static_cast<int>(in.ncols), H = static_cast<int>(in.nrows), ss = m_options.supersampling;
	cv::Mat acc(H, W, m_options.grey ? CV_64FC1 : CV_64FC3, cv::Scalar::all(0));
	// ss x ss samples per pixel in an N-rooks pattern: one per cell of an ss x ss grid, shifted within its cell so
	// that all ss^2 samples have distinct columns and distinct rows (sample (i, j) at x = (i + (j + 0.5) / ss) / ss,
	// y = (j + (i + 0.5) / ss) / ss of the pixel). A texture edge crossing the pixel then changes its value in ss^2
	// steps instead of ss (a regular ss x ss grid moves edges in steps of 1 / ss px as the camera moves, which the
	// tracker sees as up to 1 / (2 ss) px of flow error). Every sample column shares its horizontal ray hits.
	for (int u = 0; u < W; ++u)
		for (int i = 0; i < ss; ++i)
			for (int j = 0; j < ss; ++j)
			{
				THorizontal cache;
				const double xc = (u - 0.5 + (i + (j + 0.5) / ss) / ss - in.cx()) / in.fx();
				const double dy = -0.5 + (j + (i + 0.5) / ss) / ss;
				for (int v = 0; v < H; ++v)
				{
					const double yc = (v + dy - in.cy()) / in.fy();
					const double d[3] = {R(0, 0) * xc + R(0, 1) * yc + R(0, 2), R(1, 0) * xc + R(1, 1) * yc + R(1, 2),
										 R(2, 0) * xc + R(2, 1) * yc + R(2, 2)};
					const TSample s = shade(ctx, d, cache);
					if (m_options.grey)
						acc.at<double>(v, u) += s.grey;
					else
						acc.at<cv::Vec3d>(v, u) += s.grey * tintOf(s.surface);
				}
			}
	std::normal_distribution<double> noise(0.0, m_options.noise_grey);
	acc *= 1.0 / (ss * ss);
	if (m_options.noise_grey > 0)
	{
		double* p = acc.ptr<double>();  // continuous
		for (size_t i = 0; i < acc.total() * acc.channels(); ++i) p[i] += noise(rng);
	}
	auto obs = mrpt::obs::CObservationImage::Create();
	obs->sensorLabel = m_options.label;
	obs->cameraParams = in;
	obs->cameraPose = m_camera.sensorPose;
	obs->image = mrpt::img::CImage(W, H, m_options.grey ? mrpt::img::CH_GRAY : mrpt::img::CH_RGB);
	acc.convertTo(obs->image.asCvMatRef(), m_options.grey ? CV_8UC1 : CV_8UC3);
	return obs;
}

std::optional<mrpt::math::TPoint3D> CPinholeCameraSimulator::surfacePoint(const CWorld& world,
																		   const mrpt::math::TPose2D& robot, double u_px,
																		   double v_px) const
{
	const auto& in = m_camera.intrinsics;
	const mrpt::poses::CPose3D cam = mrpt::poses::CPose3D(robot.x, robot.y, 0, robot.phi, 0, 0) + m_camera.sensorPose;
	const auto R = cam.getRotationMatrix();
	const CWorld people = peopleWorld(world, m_options.person_radius_m);
	const TRenderContext ctx{world, people, m_options, TPoint2D{cam.x(), cam.y()}, cam.z()};
	const double xc = (u_px - in.cx()) / in.fx(), yc = (v_px - in.cy()) / in.fy();
	const double d[3] = {R(0, 0) * xc + R(0, 1) * yc + R(0, 2), R(1, 0) * xc + R(1, 1) * yc + R(1, 2),
						 R(2, 0) * xc + R(2, 1) * yc + R(2, 2)};
	THorizontal cache;
	const TSample s = shade(ctx, d, cache);
	if (s.surface == ESurface::none || !(s.lambda > 0)) return std::nullopt;
	return mrpt::math::TPoint3D(xc * s.lambda, yc * s.lambda, s.lambda);
}

}  // namespace hslam::sim
