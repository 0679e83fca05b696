/* hslam-bench: helpers shared by the benchmark suites. */
#pragma once

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <chrono>
#include <string>
#include <vector>

namespace hslam::bench
{
/** A laser scan with the robot pose it was taken at. */
struct TPosedScan
{
	mrpt::poses::CPose2D pose;
	mrpt::obs::CObservation2DRangeScan scan;
};

/** Reads every 2D scan of a rawlog with its dead-reckoning pose. */
std::vector<TPosedScan> loadPosedScans(const std::string& rawlogPath);

/** Wall time of fn() in seconds, the best of `repetitions` runs (the
 * minimum is the most repeatable figure on a shared machine). */
template <class F>
double bestTimeOf(int repetitions, F&& fn)
{
	double best = 1e300;
	for (int r = 0; r < repetitions; ++r)
	{
		const auto t0 = std::chrono::steady_clock::now();
		fn();
		const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
		best = std::min(best, dt.count());
	}
	return best;
}

/** The MRPT sample rawlog shipped with mrpt-common (real laser + odometry). */
inline const char* kMrptSampleRawlog = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

int runGridSuite(const std::vector<std::string>& rawlogs, int repetitions);
int runHwdriversSuite(int repetitions);

}  // namespace hslam::bench
