/* hslam calib: UMBmark end-point errors from a recorded run (thesis 4.1).
 *
 * Input is a time-ordered sequence of (true pose, odometry pose) pairs that
 * starts where the first run starts: either the corners of the squares only
 * (the simulator's waypoints.csv) or every odometry reading of a recording
 * (with the true pose from ground truth). Runs follow each other without a
 * reset, as in the thesis's experiment and rawlog_samples/umbmark.
 *
 * A run ends at the first closest approach of the odometry to the run's start
 * position once the path has gone around (travelled more than twice its
 * largest distance from the start); the next run starts there. Direction: sign
 * of the area the odometry path encloses (negative = CW). L = travelled / 4.
 *
 * The error of a run is measured as if its start had no error: the TRUE
 * relative motion of the run is composed onto the ODOMETRY start pose and
 * compared with the odometry end,
 *     e = (odo_start (+) (true_start^-1 (+) true_end)).xy - odo_end.xy,
 * rotated into the run's frame (+x along the first leg). The robot's response
 * to the same commands does not depend on where it is, so this equals the
 * error of a run started exactly on the marks. */
#pragma once

#include <hslam/calib/umbmark.h>
#include <mrpt/poses/CPose2D.h>

#include <vector>

namespace hslam::calib
{
struct TPosePair
{
	double t_s = 0;
	mrpt::poses::CPose2D truth;
	mrpt::poses::CPose2D odometry;
};

struct TRunSplitOptions
{
	/** The odometry must come back within this fraction of the side length. */
	double closure_fraction = 0.1;
	/** Runs shorter than this are ignored (m). */
	double min_run_length_m = 1.0;
};

struct TSplitRuns
{
	std::vector<TUmbmarkEndpoint> endpoints;
	std::vector<double> side_lengths_m;  //!< per run, travelled / 4
	double mean_side_length_m = 0;
};

/** Splits `samples` into runs and measures each run's end-point error. */
TSplitRuns splitUmbmarkRuns(const std::vector<TPosePair>& samples, const TRunSplitOptions& options = {});

/** Error of one run (see the file comment), in the frame whose +x is `firstLegHeading_rad`. */
TUmbmarkEndpoint runEndpointError(const TPosePair& start, const TPosePair& end, double firstLegHeading_rad,
								  bool clockwise);

}  // namespace hslam::calib
