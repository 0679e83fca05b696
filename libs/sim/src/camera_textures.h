/* hslam sim: procedural surface textures of the simulated camera (private to
 * CPinholeCameraSimulator). Pure functions of world coordinates. */
#pragma once

#include <cstdint>

namespace hslam::sim::textures
{
/** Uniform [0, 1) from integer coordinates and a key (splitmix64 hash). */
double hash01(int64_t a, int64_t b, int64_t key);

/** Wall: bricks 0.30 x 0.15 m (every other row offset by half) with blocks of
 * 0.06 m inside; s_m along the wall, z_m height; key identifies the wall line. */
double wallGrey(double s_m, double z_m, int64_t key);
/** Floor (ceiling with another key): tiles of 0.4 m with speckle of 0.08 m. */
double floorGrey(double x_m, double y_m, int64_t key);
/** Person: horizontal bands (clothes) and blocks around the cylinder. */
double personGrey(double angle_rad, double z_m, int64_t personId);

}  // namespace hslam::sim::textures
