/* hslam-bench vision: image pairs with an exact true FOE, from the plane
 * warp (vision::scenarioPair, plane_warp.h) and from the simulator's camera
 * (sim::CPinholeCameraSimulator) in the static lab scene
 * (config_ini/sim-worlds/lab.scene, people left out). */
#include "bench_vision_pairs.h"

#include "bench_vision.h"

#include <hslam/sim/CPinholeCameraSimulator.h>
#include <hslam/sim/scene.h>
#include <hslam/vision/observation_image.h>
#include <mrpt/obs/CObservationImage.h>

#include <map>
#include <random>
#include <tuple>

namespace hslam::bench
{
std::vector<TTruthPair> planePairs(const vision::TMountedCamera& camera, vision::EPlaneMotion motion, int pairs,
								   uint64_t seed)
{
	std::vector<TTruthPair> out;
	for (int k = 0; k < pairs; ++k)
	{
		const auto spec = vision::scenarioPair(camera, motion, k, seed);
		auto p = vision::makePlanePair(spec);
		out.push_back({std::move(p.first), std::move(p.second), spec.robot_yaw_rad, p.foe});
	}
	return out;
}

namespace
{
cv::Mat renderGrey(const sim::CPinholeCameraSimulator& cam, const sim::CWorld& world, const mrpt::poses::CPose2D& pose,
				   std::mt19937_64& rng)
{
	const auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(cam.render(world, pose.asTPose(), rng));
	if (!obs) throw std::runtime_error("the simulator camera rendered no CObservationImage");
	return vision::greyImageOf(*obs);
}
}  // namespace

std::vector<TTruthPair> renderedPairs(int width, int height, bool rotate, int pairs, uint64_t seed)
{
	// The FOE rows and the timing rows use the same pairs: render each set once (cv::Mat copies share the pixels).
	static std::map<std::tuple<int, int, bool, int, uint64_t>, std::vector<TTruthPair>> rendered;
	const auto key = std::make_tuple(width, height, rotate, pairs, seed);
	if (const auto it = rendered.find(key); it != rendered.end()) return it->second;
	sim::TCameraSimOptions o;
	o.enabled = true;
	o.intrinsics.width_px = width;
	o.intrinsics.height_px = height;
	const sim::CPinholeCameraSimulator cam(o);
	const sim::CWorld world = sim::loadSceneFile(kLabScene).world;
	cv::RNG rng(seed);
	std::mt19937_64 noise(seed);
	std::vector<TTruthPair> out;
	const double deg = M_PI / 180.0;
	for (int k = 0; k < pairs; ++k)
	{
		// Robot in the west half of the room looking roughly east (the pillar,
		// chairs, table and far walls in view), forward 5-10 cm (thesis 4.8.3).
		const mrpt::poses::CPose2D p0(rng.uniform(1.0, 3.5), rng.uniform(1.5, 5.0), rng.uniform(-20.0, 20.0) * deg);
		const double d = rng.uniform(0.05, 0.10);
		const double yaw = rotate ? (rng.uniform(0, 2) ? 1 : -1) * rng.uniform(1.0, 3.0) * deg : 0.0;
		const mrpt::poses::CPose3D delta(d * std::cos(0.5 * yaw), d * std::sin(0.5 * yaw), 0, yaw, 0, 0);
		const mrpt::poses::CPose2D p1 = p0 + mrpt::poses::CPose2D(delta);
		out.push_back({renderGrey(cam, world, p0, noise), renderGrey(cam, world, p1, noise), yaw,
					   vision::trueFoeOfRobotMotion(cam.camera(), delta)});
	}
	rendered[key] = out;
	return out;
}

}  // namespace hslam::bench
