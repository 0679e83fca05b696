/* hslam: the files of the camera branch in the batch output folder:
 *   vision.csv          one row per analysed image pair: tracks, FOE (least
 *                       squares and vote), confidence, moving-object cues
 *   vision/frame_N.png  debug panels ([vision] debug_every_frames): flow,
 *                       predicted rotation flow, residual, column votes + FOE
 * Nothing is written when the run had no camera images. */
#pragma once

#include <hslam/slam/CVisionStage.h>

#include <ostream>
#include <string>
#include <vector>

namespace hslam::slam
{
/** vision.csv: one row per analysed pair. */
void writeVisionCsv(const std::vector<TVisionRow>& rows, std::ostream& out);

/** Writes vision.csv and vision/frame_N.png into `dir`; appends the paths to `written`. */
void writeVisionOutputs(const CVisionStage& stage, const std::string& dir, std::vector<std::string>& written);

}  // namespace hslam::slam
