/* hslam: the three synthetic environments of thesis table 3 (4.4.4), as wall
 * lists for simulateScan(), seen by a 181-beam, 180 deg scanner at the origin
 * looking along +x:
 *   1. "room10": a room whose 10 walls are all in view (a star-shaped
 *      polygon, so none hides another), direction changes at the corners between 29 and 110 deg
 *      (thesis figure 98: 10 lines);
 *   2. "corner2": two walls meeting in a corner, the front one much noisier
 *      (thesis figure 101: "despite the noisy lines on the right");
 *   3. "lines3": three separate walls with open space (no echo) between them
 *      (thesis figure 102).
 * The thesis gives the environments only as figures; these reproduce their
 * description, not their exact coordinates. */
#pragma once

#include <hslam/benchdata/synthetic_scan.h>

#include <string>
#include <vector>

namespace hslam::benchdata
{
struct TWallScene
{
	std::string name;
	std::vector<TWall> walls;
};

/** The three scenes; every wall has range noise `sigma_m`, the noisy wall of
 * "corner2" has `noisy_sigma_m`. */
std::vector<TWallScene> thesisTable3Scenes(double sigma_m, double noisy_sigma_m);

}  // namespace hslam::benchdata
