/* hslam: which CARMEN range values mean "no return", and scan.maxRange.
 *
 * Measured on 13 real CARMEN logs: the no-return value differs per log
 * (about 81.9, 51.1, exactly 50.0, 32.76 m) while real returns reach 79 m, so
 * no fixed cap works. The value is derived from the log: the largest per-scan
 * maximum that is the exact maximum of at least max(kMinMarkerScans, kMinMarkerScanFraction * scans)
 * scans is the no-return marker (a real return at a maximum happens once or
 * twice, a marker in many scans). Scans whose maximum is above the marker (a corrupt 1e308 beam, one
 * 82.5 m beam in intel) are outliers: counted, their beams >= marker invalid;
 * they no longer turn the no-return handling off for the whole log (the
 * global maximum did, issue 15 item 2). Then beams >= marker - kNoReturnTolerance_m and beams <= 0 are
 * invalid and maxRange = marker. Without a marker, maxRange = PARAM
 * robot_front_laser_max if given, else the largest range, and only beams <= 0
 * are invalid. A user-given maximum overrides both (beams >= it are invalid). */
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hslam::io
{
constexpr double kNoReturnTolerance_m = 1e-6;
constexpr size_t kMinMarkerScans = 3;
constexpr double kMinMarkerScanFraction = 0.01;

struct TCarmenRangeLimits
{
	double maxRange_m = 0;  //!< goes to CObservation2DRangeScan::maxRange
	std::optional<double> noReturn_m;  //!< beams >= this - tolerance are invalid
	std::string reason;  //!< how the values were derived
	size_t outlierScans = 0;  //!< scans with a maximum above the no-return marker
	double largestOutlier_m = 0;

	/** True for a real return: r > 0 and below the no-return value. */
	bool isValid(double range_m) const;
};

/** Largest value of `ranges_m` (nullopt for an empty scan). */
std::optional<double> scanMaximum(const std::vector<double>& ranges_m);

/** Derives the limits from the per-scan maxima of all scans of the log.
 * `paramLaserMax_m`: PARAM robot_front_laser_max if present; `override_m`:
 * user-given maximum, <= 0 for none. */
TCarmenRangeLimits deriveCarmenRangeLimits(const std::vector<double>& scanMaxima_m,
										   std::optional<double> paramLaserMax_m, double override_m);

}  // namespace hslam::io
