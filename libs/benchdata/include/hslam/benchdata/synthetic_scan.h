/* hslam: exact 2D laser scans of a world made of wall segments, with the
 * ground-truth visible part of every wall - the fixtures of the line
 * extraction tests and of `hslam-bench lines` (thesis table 3 environments).
 *
 * Each beam is cast from the sensor (robot pose (+) scan.sensorPose) and ends
 * on the nearest wall; its range gets Gaussian noise with that wall's sigma.
 * A beam that hits nothing within maxRange returns maxRange with its
 * validity flag off (the "no echo" convention of MRPT scans). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hslam::benchdata
{
struct TWall
{
	mrpt::math::TPoint2D a, b;  //!< end points, world frame (m)
	double noise_sigma_m = 0;  //!< range noise of beams ending on this wall
};

struct TScanLayout
{
	size_t beams = 181;
	double aperture_rad = M_PI;
	double max_range_m = 10;
};

struct TSyntheticScan
{
	mrpt::obs::CObservation2DRangeScan scan;
	std::vector<int> wall_of_beam;  //!< index of the wall each beam hit, -1 for none
	std::vector<double> true_range_m;  //!< noiseless range (0 for none)
};

/** Ray-casts `walls` from `robotPose` (the scan's sensorPose is the identity). */
TSyntheticScan simulateScan(const std::vector<TWall>& walls, const mrpt::poses::CPose2D& robotPose,
							const TScanLayout& layout, uint32_t noiseSeed);

/** The part of a wall seen by one unbroken run of beams, in the robot frame:
 * the exact hit points of its first and last beam. */
struct TVisibleWall
{
	size_t wall = 0;
	size_t first_beam = 0, last_beam = 0;
	mrpt::math::TPoint2D p0, p1;
	double length_m() const;
};

/** Visible wall parts seen by at least min_beams beams and at least min_length_m long. */
std::vector<TVisibleWall> visibleWalls(const TSyntheticScan& sim, size_t min_beams, double min_length_m);

}  // namespace hslam::benchdata
