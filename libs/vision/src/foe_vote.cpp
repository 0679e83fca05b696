#include <hslam/vision/foe.h>

#include <cmath>

namespace hslam::vision
{
namespace
{
/** Middle of the bin of the first sign change (empty bins skipped), or -1. */
int crossingBin(const std::vector<double>& sums)
{
	int prev = -1;
	for (int i = 0; i < static_cast<int>(sums.size()); ++i)
	{
		if (sums[i] == 0) continue;
		if (prev >= 0 && (sums[prev] > 0) != (sums[i] > 0))
			return std::abs(sums[prev]) <= std::abs(sums[i]) ? prev : i;  // the bin nearer zero holds the crossing
		prev = i;
	}
	return -1;
}

/** Sums +-value per bin of coordinate `along` by the sign of component `component`. */
std::vector<double> binSums(const std::vector<TFlowVector>& residual, int bins, double extent_px, bool alongX,
							const TFoeOptions& o)
{
	std::vector<double> sums(static_cast<size_t>(bins), 0.0);
	const double binSize = extent_px / bins;
	for (const auto& f : residual)
	{
		const cv::Point2f d = f.flow();
		if (cv::norm(d) < o.minFlow_px()) continue;
		const double pos = alongX ? f.p0.x : f.p0.y, comp = alongX ? d.x : d.y;
		const int bin = static_cast<int>(std::floor(pos / binSize));
		if (bin < 0 || bin >= bins) continue;
		sums[static_cast<size_t>(bin)] += comp > 0 ? o.vote_value : comp < 0 ? -o.vote_value : 0.0;
	}
	return sums;
}
}  // namespace

TFoeVote voteFoe(const std::vector<TFlowVector>& residual, int width, int height, const TFoeOptions& o)
{
	TFoeVote out;
	out.column_sums = binSums(residual, o.vote_columns, width, true, o);
	out.row_sums = binSums(residual, o.vote_rows, height, false, o);
	const int cx = crossingBin(out.column_sums), cy = crossingBin(out.row_sums);
	out.valid_x = cx >= 0;
	out.valid_y = cy >= 0;
	out.x_px = out.valid_x ? (cx + 0.5) * width / o.vote_columns : 0.5 * width;
	out.y_px = out.valid_y ? (cy + 0.5) * height / o.vote_rows : 0.5 * height;
	return out;
}

}  // namespace hslam::vision
