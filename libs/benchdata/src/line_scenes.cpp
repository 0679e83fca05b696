/* hslam: thesis table 3 environments (see line_scenes.h). */
#include <hslam/benchdata/line_scenes.h>

#include <cmath>

namespace hslam::benchdata
{
namespace
{
/** Closed-free polyline through points given in polar form (deg, m). */
std::vector<TWall> polarPolyline(const std::vector<std::pair<double, double>>& vertices, double sigma_m)
{
	std::vector<TWall> walls;
	for (size_t i = 0; i + 1 < vertices.size(); ++i)
	{
		auto at = [&](size_t k) {
			const double a = vertices[k].first * M_PI / 180;
			return mrpt::math::TPoint2D(vertices[k].second * std::cos(a), vertices[k].second * std::sin(a));
		};
		walls.push_back({at(i), at(i + 1), sigma_m});
	}
	return walls;
}
}  // namespace

std::vector<TWallScene> thesisTable3Scenes(double sigma_m, double noisy_sigma_m)
{
	std::vector<TWallScene> scenes;
	scenes.push_back({"room10", polarPolyline({{-100, 1.6},
											   {-68, 2.6},
											   {-45, 3.6},
											   {-22, 2.7},
											   {-5, 4.0},
											   {12, 3.1},
											   {30, 4.2},
											   {48, 3.0},
											   {65, 3.6},
											   {82, 2.6},
											   {105, 3.0}},
											  sigma_m)});
	scenes.push_back({"corner2",
					  {{{3.0, -4.0}, {3.0, 2.0}, noisy_sigma_m},  // front wall (the noisy one)
					   {{3.0, 2.0}, {-1.0, 2.0}, sigma_m}}});  // left wall
	scenes.push_back({"lines3",
					  {{{0.5, -1.5}, {2.5, -2.0}, sigma_m},  // right
					   {{3.5, -1.0}, {3.5, 1.2}, sigma_m},  // front
					   {{2.5, 1.8}, {0.3, 2.6}, sigma_m}}});  // left
	return scenes;
}

}  // namespace hslam::benchdata
