/* hslam: summary statistics (count, mean, RMSE, max) of a list of
 * non-negative error magnitudes, shared by ATE and RPE. */
#pragma once

#include <cstddef>
#include <vector>

namespace hslam::eval
{
/** Statistics of error magnitudes; the unit is that of the errors and is
 * given by the name of the member that holds the struct (e.g. `trans_m`). */
struct TErrorStats
{
	size_t count = 0;  //!< number of errors; 0 means "no data" (other fields 0)
	double mean = 0;
	double rmse = 0;
	double max = 0;

	bool empty() const { return count == 0; }
};

/** Computes count, mean, root mean square and maximum of `errors`. */
TErrorStats computeErrorStats(const std::vector<double>& errors);

}  // namespace hslam::eval
