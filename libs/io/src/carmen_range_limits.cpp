/* hslam: no-return detection and max range of a CARMEN log. */
#include <hslam/io/carmen_range_limits.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "text_format.h"

namespace hslam::io
{
namespace
{
using detail::formatNumber;

size_t requiredMarkerScans(size_t scanCount)
{
	const auto fraction = static_cast<size_t>(std::ceil(kMinMarkerScanFraction * static_cast<double>(scanCount)));
	return std::max(kMinMarkerScans, fraction);
}

struct TMarkerCandidate
{
	double value_m = 0;
	size_t scans = 0;
};

/** The largest value that is the exact maximum of at least `required` scans
 * (else the most frequent maximum, to explain the refusal). A no-return
 * marker is the maximum of many scans; a single outlier beam (1e308, or a
 * glitch a little above the marker) is the maximum of one scan and so cannot
 * become the marker, unlike the global maximum (issue 15, item 2). */
TMarkerCandidate largestRepeatedMaximum(const std::vector<double>& scanMaxima_m, size_t required)
{
	std::map<double, size_t> counts;
	for (double m : scanMaxima_m)
		if (std::isfinite(m)) ++counts[m];
	TMarkerCandidate best, mode;
	for (const auto& [value_m, n] : counts)
	{
		if (n >= required) best = {value_m, n};  // ascending: the last one is the largest
		if (n >= mode.scans) mode = {value_m, n};
	}
	return best.scans > 0 ? best : mode;
}

TCarmenRangeLimits withoutMarker(double globalMax_m, std::optional<double> paramLaserMax_m, const std::string& why)
{
	TCarmenRangeLimits limits;
	limits.maxRange_m = paramLaserMax_m ? *paramLaserMax_m : globalMax_m;
	limits.reason = why + "; maxRange = " + formatNumber(limits.maxRange_m) + " m from " +
					(paramLaserMax_m ? "PARAM robot_front_laser_max" : "the largest range in the log") +
					"; only ranges <= 0 are invalid";
	return limits;
}
}  // namespace

bool TCarmenRangeLimits::isValid(double range_m) const
{
	if (!(range_m > 0)) return false;
	return !noReturn_m || range_m < *noReturn_m - kNoReturnTolerance_m;
}

std::optional<double> scanMaximum(const std::vector<double>& ranges_m)
{
	if (ranges_m.empty()) return std::nullopt;
	return *std::max_element(ranges_m.begin(), ranges_m.end());
}

TCarmenRangeLimits deriveCarmenRangeLimits(const std::vector<double>& scanMaxima_m,
										   std::optional<double> paramLaserMax_m, double override_m)
{
	if (override_m > 0)
	{
		TCarmenRangeLimits limits;
		limits.maxRange_m = override_m;
		limits.noReturn_m = override_m;
		limits.reason = "given by the user: ranges >= " + formatNumber(override_m) + " m and <= 0 are invalid";
		return limits;
	}
	if (scanMaxima_m.empty()) return withoutMarker(0.0, paramLaserMax_m, "no scans");
	const double globalMax_m = *std::max_element(scanMaxima_m.begin(), scanMaxima_m.end());
	const size_t required = requiredMarkerScans(scanMaxima_m.size());
	const auto marker = largestRepeatedMaximum(scanMaxima_m, required);
	const std::string counted = "the scan maximum " + formatNumber(marker.value_m) + " m is the maximum of " +
								std::to_string(marker.scans) + " of " + std::to_string(scanMaxima_m.size()) + " scans";
	if (!(marker.value_m > 0) || marker.scans < required)
		return withoutMarker(globalMax_m, paramLaserMax_m,
							 counted + " (< " + std::to_string(required) + " needed): no no-return marker");
	TCarmenRangeLimits limits;
	limits.maxRange_m = marker.value_m;
	limits.noReturn_m = marker.value_m;
	for (double m : scanMaxima_m)
		if (m > marker.value_m) ++limits.outlierScans;
	limits.largestOutlier_m = globalMax_m;
	limits.reason = counted + " (>= " + std::to_string(required) + "): it is the no-return marker; ranges >= " +
					formatNumber(marker.value_m) + " m and <= 0 are invalid";
	if (limits.outlierScans > 0)
		limits.reason += "; " + std::to_string(limits.outlierScans) + " scans with larger (outlier) ranges up to " +
						 formatNumber(globalMax_m) + " m: those beams are invalid";
	return limits;
}

}  // namespace hslam::io
