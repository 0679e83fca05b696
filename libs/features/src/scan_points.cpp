/* hslam: valid scan points in the robot frame (see scan_points.h). */
#include <hslam/features/scan_points.h>


namespace hslam::features
{
std::vector<TIndexRange> consecutiveBeamRuns(const TScanPoints& points)
{
	std::vector<TIndexRange> runs;
	for (size_t i = 0; i < points.size(); ++i)
	{
		if (runs.empty() || points.beam[i] != points.beam[i - 1] + 1) runs.push_back({i, i});
		runs.back().end = i + 1;
	}
	return runs;
}

}  // namespace hslam::features
