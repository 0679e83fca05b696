/* hslam: the files of the loop-closure stage in the batch output folder
 * (issue 13, part 5):
 *   trajectory_online.tum  the front-end's filtered pose per scan (trajectory.tum
 *                          then holds the pose corrected by the pose graph)
 *   loop_closures.csv      every tested closure: keyframe ids (= scan indices),
 *                          accepted or why not, scores, relative pose
 *   graph.graph            the pose graph in MRPT's .graph text format
 *                          (CNetworkOfPoses2DInf::loadFromTextFile reads it)
 *   map_loop_closures.png  map.png with every tested closure drawn between its
 *                          two keyframes (drawLoopClosures; batch_outputs.cpp)
 * and the back-end's timing lines appended to timing.txt.
 * Nothing is written when the stage is off. */
#pragma once

#include <hslam/maps/grid_rendering.h>
#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/img/CImage.h>

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace hslam::slam
{
/** Human-readable back-end figures (keyframes, closures, time), one per line. */
void printLoopClosureTiming(const CLoopClosureStage& stage, std::ostream& out);

/** The tested closures that were not accepted, counted by their reason
 * (loop_closures.csv's "reason": "low score", "ambiguous", ...). */
std::map<std::string, size_t> rejectedClosuresByReason(const CLoopClosureStage& stage);

/** Draws every tested closure as a line between the optimised poses of its
 * query and anchor keyframes: accepted ones green and 2 px wide (dropped by
 * the optimiser: orange), rejected ones thin blue, drawn first so accepted
 * ones stay visible. Returns the number of lines drawn. */
size_t drawLoopClosures(mrpt::img::CImage& image, const maps::TImageFrame& frame, const CLoopClosureStage& stage);

/** Writes the files above into `dir`; appends the paths to `written`. */
void writeLoopClosureOutputs(const CMappingPipeline& pipeline, const std::string& dir,
							 std::vector<std::string>& written);

}  // namespace hslam::slam
