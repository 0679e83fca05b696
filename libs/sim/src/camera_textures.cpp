#include "camera_textures.h"

#include <cmath>

namespace hslam::sim::textures
{
double hash01(int64_t a, int64_t b, int64_t key)
{
	uint64_t z = static_cast<uint64_t>(a) * 0x9E3779B97F4A7C15ULL ^ static_cast<uint64_t>(b) * 0xC2B2AE3D27D4EB4FULL ^
				 static_cast<uint64_t>(key) * 0x165667B19E3779F9ULL;
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	z ^= z >> 31;
	return static_cast<double>(z >> 11) * (1.0 / 9007199254740992.0);
}

namespace
{
int64_t cell(double v, double size) { return static_cast<int64_t>(std::floor(v / size)); }
}  // namespace

double wallGrey(double s_m, double z_m, int64_t key)
{
	const int64_t row = cell(z_m, 0.15);
	const double shifted = s_m + (row % 2 ? 0.15 : 0.0);
	const double brick = hash01(cell(shifted, 0.30), row, key);
	const double block = hash01(cell(s_m, 0.06), cell(z_m, 0.06), key + 17);
	const bool mortar = std::fmod(std::abs(z_m), 0.15) < 0.012 || std::fmod(std::abs(shifted), 0.30) < 0.012;
	return mortar ? 60.0 : 70.0 + 120.0 * brick + 50.0 * (block - 0.5);
}

double floorGrey(double x_m, double y_m, int64_t key)
{
	const double tile = hash01(cell(x_m, 0.4), cell(y_m, 0.4), key);
	const double speck = hash01(cell(x_m, 0.08), cell(y_m, 0.08), key + 5);
	return 90.0 + 100.0 * tile + 40.0 * (speck - 0.5);
}

double personGrey(double angle_rad, double z_m, int64_t personId)
{
	const double band = hash01(cell(z_m, 0.25), 0, personId * 31 + 7);
	const double block = hash01(cell(angle_rad, 0.5), cell(z_m, 0.1), personId * 31 + 11);
	return 30.0 + 150.0 * band + 60.0 * (block - 0.5);
}

}  // namespace hslam::sim::textures
