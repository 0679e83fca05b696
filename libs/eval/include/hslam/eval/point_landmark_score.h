/* hslam: scoring point landmarks (e.g. TBF sonar corners, thesis 4.3)
 * against true positions (a simulator's corners.csv): precision = share of
 * the found points within `radius_m` of some true point, recall = share of
 * the true points with a found point within `radius_m`. Also reads the x/y
 * columns of a CSV with a header naming them (x_m, y_m). */
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace hslam::eval
{
struct TPointLandmarkScore
{
	size_t found = 0, found_near_truth = 0;
	size_t truth = 0, truth_found = 0;
	double precision() const { return found ? static_cast<double>(found_near_truth) / found : 0.0; }
	double recall() const { return truth ? static_cast<double>(truth_found) / truth : 0.0; }
};

/** `found` are given in a frame placed at `foundFrameInTruth` in the truth
 * frame. `truthRadii` (empty = all 0, else one per true point): true points
 * that are discs (a pillar echoes from its surface, not its centre); the
 * distance to a disc is the distance to its surface. */
TPointLandmarkScore scorePointLandmarks(const std::vector<mrpt::math::TPoint2D>& found,
										const std::vector<mrpt::math::TPoint2D>& truth, double radius_m,
										const mrpt::poses::CPose2D& foundFrameInTruth = {},
										const std::vector<double>& truthRadii = {});

/** Columns x_m and y_m of a CSV file with a header line; throws
 * std::runtime_error naming file and line on a missing column or bad number. */
std::vector<mrpt::math::TPoint2D> readPointsCsv(const std::string& path);

}  // namespace hslam::eval
