/* hslam calib: UMBmark runs from pose sequences (see umbmark_runs.h). */
#include <hslam/calib/umbmark_runs.h>

#include <cmath>
#include <string>

namespace hslam::calib
{
TUmbmarkEndpoint runEndpointError(const TPosePair& start, const TPosePair& end, double heading, bool clockwise)
{
	const mrpt::poses::CPose2D trueRelative = end.truth - start.truth;  // true_start^-1 (+) true_end
	const mrpt::poses::CPose2D ideal = start.odometry + trueRelative;
	const double ex = ideal.x() - end.odometry.x(), ey = ideal.y() - end.odometry.y();
	TUmbmarkEndpoint e;
	e.clockwise = clockwise;
	e.err_x_m = std::cos(heading) * ex + std::sin(heading) * ey;
	e.err_y_m = -std::sin(heading) * ex + std::cos(heading) * ey;
	return e;
}

namespace
{
double distance(const mrpt::poses::CPose2D& a, const mrpt::poses::CPose2D& b)
{
	return std::hypot(a.x() - b.x(), a.y() - b.y());
}

/** Index of the sample that ends the run starting at `first`, or 0 if none. */
size_t findRunEnd(const std::vector<TPosePair>& s, size_t first, const TRunSplitOptions& o)
{
	double travelled = 0, farthest = 0;
	size_t best = 0;
	double bestDist = 0;
	for (size_t i = first + 1; i < s.size(); ++i)
	{
		travelled += distance(s[i].odometry, s[i - 1].odometry);
		const double d = distance(s[i].odometry, s[first].odometry);
		farthest = std::max(farthest, d);
		const bool closed = travelled > o.min_run_length_m && travelled > 2.0 * farthest &&
							d < o.closure_fraction * travelled / 4.0;
		if (closed && (best == 0 || d < bestDist - 1e-4))
		{
			best = i;
			bestDist = d;
		}
		else if (best != 0 && !closed)
			return best;  // left the closure zone: the closest approach was the end
		else if (best != 0 && d > bestDist + 0.05)
			return best;  // moving away again (next run already under way)
	}
	return best;
}

/** Signed area (shoelace) and first-leg heading of the odometry path s[a..b]. */
void runShape(const std::vector<TPosePair>& s, size_t a, size_t b, double& area, double& heading, double side)
{
	area = 0;
	heading = 0;
	bool headingFound = false;
	const auto& o = s[a].odometry;
	for (size_t i = a + 1; i <= b; ++i)
	{
		const double x0 = s[i - 1].odometry.x() - o.x(), y0 = s[i - 1].odometry.y() - o.y();
		const double x1 = s[i].odometry.x() - o.x(), y1 = s[i].odometry.y() - o.y();
		area += 0.5 * (x0 * y1 - x1 * y0);
		if (!headingFound && std::hypot(x1, y1) > 0.25 * side)
		{
			heading = std::atan2(y1, x1);
			headingFound = true;
		}
	}
}
}  // namespace

TSplitRuns splitUmbmarkRuns(const std::vector<TPosePair>& s, const TRunSplitOptions& o)
{
	TSplitRuns out;
	size_t start = 0;
	while (start + 1 < s.size())
	{
		const size_t end = findRunEnd(s, start, o);
		if (end == 0) break;
		double travelled = 0;
		for (size_t i = start + 1; i <= end; ++i) travelled += distance(s[i].odometry, s[i - 1].odometry);
		const double side = travelled / 4.0;
		double area = 0, heading = 0;
		runShape(s, start, end, area, heading, side);
		TUmbmarkEndpoint e = runEndpointError(s[start], s[end], heading, area < 0);
		e.label = "run " + std::to_string(out.endpoints.size() + 1) + " (t " + std::to_string(s[start].t_s) + " .. " +
				  std::to_string(s[end].t_s) + " s)";
		out.endpoints.push_back(e);
		out.side_lengths_m.push_back(side);
		start = end;
	}
	double sum = 0;
	for (double l : out.side_lengths_m) sum += l;
	if (!out.side_lengths_m.empty()) out.mean_side_length_m = sum / out.side_lengths_m.size();
	return out;
}

}  // namespace hslam::calib
