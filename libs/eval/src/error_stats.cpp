/* hslam: count / mean / RMSE / max of error magnitudes. */
#include <hslam/eval/error_stats.h>

#include <algorithm>
#include <cmath>

namespace hslam::eval
{
TErrorStats computeErrorStats(const std::vector<double>& errors)
{
	TErrorStats s;
	if (errors.empty()) return s;
	double sum = 0, sumSquares = 0;
	for (const double e : errors)
	{
		sum += e;
		sumSquares += e * e;
		s.max = std::max(s.max, e);
	}
	s.count = errors.size();
	s.mean = sum / static_cast<double>(s.count);
	s.rmse = std::sqrt(sumSquares / static_cast<double>(s.count));
	return s;
}

}  // namespace hslam::eval
