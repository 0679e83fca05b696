/* Shared fixtures of the line extraction tests: exact ray-cast scenes. */
#pragma once

#include <hslam/features/CLineExtractor.h>
#include <hslam/benchdata/synthetic_scan.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>

#include <memory>
#include <string>
#include <vector>

namespace hslam::features::test
{
/** Box room seen from the origin (x ahead): right wall y = -3, front wall
 * x = 4 (vertical in the robot frame), left wall y = 2. Corners at
 * atan2(-3, 4) = -36.87 deg (between beams 53 and 54) and atan2(2, 4) =
 * 26.57 deg (between beams 116 and 117). */
inline std::vector<benchdata::TWall> boxRoom(double sigma_m)
{
	return {{{-1, -3}, {4, -3}, sigma_m}, {{4, -3}, {4, 2}, sigma_m}, {{4, 2}, {-1, 2}, sigma_m}};
}
constexpr double kRightCornerBeam = 90 - 36.869897645844;  // 53.13
constexpr double kLeftCornerBeam = 90 + 26.565051177078;  // 116.57

inline benchdata::TSyntheticScan simulate(const std::vector<benchdata::TWall>& walls, uint32_t seed = 1,
							   const mrpt::poses::CPose2D& pose = mrpt::poses::CPose2D())
{
	return benchdata::simulateScan(walls, pose, benchdata::TScanLayout(), seed);
}

/** Extractor with default options; MRPT's RANSAC generator is seeded so runs repeat. */
inline std::unique_ptr<CLineExtractor> defaultExtractor(const std::string& method)
{
	mrpt::random::getRandomGenerator().randomize(7);
	const mrpt::config::CConfigFileMemory empty;
	return createLineExtractor(method, empty, lineExtractorSection(method));
}

}  // namespace hslam::features::test
