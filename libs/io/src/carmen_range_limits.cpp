/* hslam: no-return detection and max range of a CARMEN log. */
#include <hslam/io/carmen_range_limits.h>

#include <algorithm>
#include <cmath>

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
	const auto atMax = static_cast<size_t>(std::count(scanMaxima_m.begin(), scanMaxima_m.end(), globalMax_m));
	const size_t required = requiredMarkerScans(scanMaxima_m.size());
	const std::string counted = "the largest range " + formatNumber(globalMax_m) + " m is the maximum of " +
								std::to_string(atMax) + " of " + std::to_string(scanMaxima_m.size()) + " scans";
	if (globalMax_m <= 0 || atMax < required)
		return withoutMarker(globalMax_m, paramLaserMax_m,
							 counted + " (< " + std::to_string(required) + " needed): no no-return marker");
	TCarmenRangeLimits limits;
	limits.maxRange_m = globalMax_m;
	limits.noReturn_m = globalMax_m;
	limits.reason = counted + " (>= " + std::to_string(required) + "): it is the no-return marker; ranges >= " +
					formatNumber(globalMax_m) + " m and <= 0 are invalid";
	return limits;
}

}  // namespace hslam::io
