/* hslam-navigate: driving the simulated P3-DX (libs/sim: kinematics with the
 * odometry errors of its INI, LMS200, sonar ring, walking people). */
#pragma once

#include "CNavigationLog.h"

#include <hslam/sim/closed_loop.h>

namespace hslam::apps
{
struct TSimDriveResult
{
	sim::TClosedLoopResult loop;
	size_t targets_reached = 0;
};

/** Drives to `targets` in the world of `simIni` (its [robot] start pose and
 * errors; path mode forced to external); logs into `log`; also writes the
 * ground truth (ground_truth.tum) and ground-truth map (gt_map.png) into outDir. */
TSimDriveResult driveSimulated(const std::string& simIni, const nav::TSubsumptionOptions& options,
							   const std::vector<mrpt::math::TPoint2D>& targets, double timeout_s, CNavigationLog& log,
							   const std::string& outDir);

}  // namespace hslam::apps
