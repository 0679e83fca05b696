/* hslam: CARMEN log -> observations-only MRPT rawlog + TUM reference file.
 *
 * Output rawlog (gz): first a CObservationComment "CARMEN_IMPORT" recording
 * source, clock, range limits, counts and conventions; then in file order,
 * per front scan (FLASER / ROBOTLASER1): a CObservationOdometry "ODOMETRY"
 * (absolute pose of our chain of raw odometry increments, see
 * CCarmenOdometryTracker.h) if the increment since the previous front scan is
 * known - or, if it is missing, a CObservationComment "ODOMETRY_GAP" instead -
 * followed by the CObservation2DRangeScan "LASER". Rear and RAWLASER scans
 * are written where they occur ("REAR_LASER", "LASER", "LASER2".."LASER4").
 * Odometry observations carry the timestamp of their scan. Consumers must not
 * difference odometry across an ODOMETRY_GAP. MRPT 2.5 does not serialize
 * the sensorLabel of a CObservationComment, so comment texts also start with
 * their label ("CARMEN_IMPORT: ...", "ODOMETRY_GAP: ...").
 * With format = frames (CRawlogFramesWriter.h) the same content is written
 * as actions + sensory frames, one frame per front scan: the action is the
 * raw odometry increment since the previous front scan as MRPT's
 * CActionRobotMovement2D (MRPT's default motion model; identity for the first
 * scan), and at an ODOMETRY_GAP the action collection is EMPTY and the gap
 * comment is in the frame; the header comment and rear/raw scans go in the
 * frame of the front scan they follow (the first frame for those before it).
 * Output TUM: one line per front scan, its reference pose (FLASER x,y,theta;
 * ROBOTLASER robot pose) with the same timestamp as the scan in the rawlog.
 *
 * Options, INI section style (all optional):
 * \code
 * [carmen_import]
 * lenient            = false  ; skip malformed lines (count them) instead of failing
 * clock              = auto   ; auto | ipc | logger | synthetic (carmen_clock.h)
 * synthetic_period_s = 1.0    ; period of the synthetic clock, seconds
 * max_range_m        = 0      ; > 0 overrides the no-return value derived from the log
 * format             = observations ; observations | frames (actions + sensory frames)
 * \endcode */
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hslam::io
{
struct TCarmenImportOptions
{
	bool lenient = false;
	std::string clock = "auto";
	double synthetic_period_s = 1.0;
	double max_range_m = 0;  //!< 0: derive from the log (carmen_range_limits.h)
	std::string format = "observations";  //!< rawlog format: observations | frames

	template <class V>
	void visit(V& v)
	{
		v.flag("lenient", lenient);
		v.choice("clock", clock, {"auto", "ipc", "logger", "synthetic"});
		v.real("synthetic_period_s", synthetic_period_s, 1e-6, 3600.0);
		v.real("max_range_m", max_range_m, 0.0, 1000.0);
		v.choice("format", format, {"observations", "frames"});
	}
};

struct TCarmenImportReport
{
	std::string inputFile, rawlogFile, tumFile;
	std::string rawlogFormat;  //!< observations | frames
	std::map<std::string, size_t> parsedMessages;  //!< per message name
	std::map<std::string, size_t> skippedMessages;  //!< per message name ("#" = comments)
	size_t malformedLinesSkipped = 0;
	std::vector<std::string> malformedExamples;  //!< the first 10, "file:line: what"
	size_t frontScans = 0, rearScans = 0, rawScans = 0;  //!< scans written
	size_t odometryObservations = 0;
	size_t odometryGaps = 0;  //!< front scans whose increment is missing
	size_t odometryAnchors = 0;  //!< ODOM lines recognised as re-anchoring
	size_t referencePoses = 0;  //!< lines of the TUM file
	std::string clockUsed, clockReason;
	double maxRange_m = 0;
	std::optional<double> noReturn_m;  //!< invalid-range threshold, if any
	std::string rangeLimitsReason;
	size_t rangeOutlierScans = 0;  //!< scans with beams above the no-return value (those beams invalid)
	std::vector<std::string> warnings;
};

/** Converts `inputLog` (plain or .gz CARMEN text). Throws std::runtime_error
 * ("file:line: what" for malformed content in strict mode, or an I/O error);
 * whatever was converted before the error is still written and closed, and
 * the message says how many scans were written. */
TCarmenImportReport convertCarmenLog(const std::string& inputLog, const std::string& outRawlog,
									 const std::string& outTum, const TCarmenImportOptions& options);

/** Human-readable multi-line summary of a report. */
std::string formatCarmenImportReport(const TCarmenImportReport& report);

}  // namespace hslam::io
