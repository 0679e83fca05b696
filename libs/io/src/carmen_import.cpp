/* hslam: convertCarmenLog, the CARMEN importer's entry point: read the log
 * (first pass), derive clock and range limits, then convert (second pass). */
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>
#include <hslam/io/carmen_import.h>
#include <hslam/io/carmen_observations.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <stdexcept>

#include "CCarmenConverter.h"
#include "text_format.h"

namespace hslam::io
{
namespace
{
using detail::formatNumber;

/** Range-checks options through their visit() description (throws config_error). */
void checkOptions(const TCarmenImportOptions& options)
{
	mrpt::config::CConfigFileMemory cfg;
	hslam::common::saveOptions(options, cfg, "carmen_import");
	TCarmenImportOptions copy;
	hslam::common::loadOptions(copy, cfg, "carmen_import");
}

struct TScanStatistics
{
	std::vector<TCarmenStamp> stamps;  //!< every scan, file order
	std::vector<double> maxima_m;  //!< per non-empty scan
};

TScanStatistics scanStatistics(const TCarmenLog& log)
{
	TScanStatistics stats;
	for (const auto& entry : log.entries)
	{
		const auto* laser = std::get_if<TCarmenLaser>(&entry.message);
		if (!laser) continue;
		stats.stamps.push_back(laser->stamp);
		if (const auto max_m = scanMaximum(laser->ranges_m)) stats.maxima_m.push_back(*max_m);
	}
	return stats;
}

std::optional<double> paramLaserMax(const TCarmenLog& log, std::vector<std::string>& warnings)
{
	const auto it = log.params.find("robot_front_laser_max");
	if (it == log.params.end()) return std::nullopt;
	const auto value = hslam::common::tryParseDouble(it->second.value);
	if (value && *value > 0) return value;
	warnings.push_back("PARAM robot_front_laser_max '" + it->second.value + "' ignored (not a positive number)");
	return std::nullopt;
}

void noteLaserOffsets(const TCarmenLaserMounts& mounts, std::vector<std::string>& warnings)
{
	if (mounts.front.x_m != 0 || mounts.front.y_m != 0 || mounts.front.yaw_rad != 0)
		warnings.push_back(
			"front laser offset is non-zero: the FLASER x,y,theta pose (CARMEN's laser_pose) is used as the robot "
			"reference pose as given");
}

std::string countsText(const std::map<std::string, size_t>& counts)
{
	std::string out;
	for (const auto& [name, count] : counts) out += (out.empty() ? "" : ", ") + name + " " + std::to_string(count);
	return out.empty() ? "none" : out;
}

std::string headerText(const TCarmenImportReport& r, const TScanStatistics& stats)
{
	return "CARMEN_IMPORT: CARMEN log imported by hslam::io::convertCarmenLog\n"
		   "source: " + r.inputFile + "\n"
		   "rawlog format: " + r.rawlogFormat + "\n"
		   "clock: " + r.clockUsed + " (" + r.clockReason + ")\n"
		   "ranges: maxRange " + formatNumber(r.maxRange_m) + " m; " + r.rangeLimitsReason + "\n"
		   "messages parsed: " + countsText(r.parsedMessages) + "; skipped: " + countsText(r.skippedMessages) +
		   "; malformed lines skipped: " + std::to_string(r.malformedLinesSkipped) + "\n"
		   "scans: " + std::to_string(stats.stamps.size()) + "\n"
		   "conventions: before each front scan an ODOMETRY observation (absolute pose of our chain of raw "
		   "odometry increments, chain_0 = last raw ODOM before the first scan) if the increment since the "
		   "previous front scan is known, else an ODOMETRY_GAP comment; odometry has the timestamp of its scan; "
		   "scans rightToLeft with aperture = (n-1)*step and the centring offset in sensorPose yaw (CARMEN's "
		   "first beam at -90 deg); the reference poses are in the TUM file, with the scan timestamps.";
}

TCarmenImportReport reportFromLog(const TCarmenLog& log, const std::string& outRawlog, const std::string& outTum)
{
	TCarmenImportReport r;
	r.inputFile = log.path;
	r.rawlogFile = outRawlog;
	r.tumFile = outTum;
	r.parsedMessages = log.parsedCounts;
	r.skippedMessages = log.skippedCounts;
	r.malformedLinesSkipped = log.malformedLines;
	r.malformedExamples = log.malformedExamples;
	return r;
}

std::string writtenSoFar(const CCarmenConverter& converter, const std::string& outRawlog, const std::string& outTum)
{
	return std::to_string(converter.scansWritten()) + " scans (" + std::to_string(converter.reference().size()) +
		   " reference poses) converted before it were written to " + outRawlog + " and " + outTum;
}

void writeTumKeepingFirstError(const std::string& path, const hslam::common::TTrajectory2D& reference)
{
	try
	{
		hslam::common::writeTumFile(path, reference);
	}
	catch (const std::exception&)
	{
		// Already failing: the first error is the one worth reporting.
	}
}

/** Second pass; on any error closes the outputs with what was converted and rethrows. */
void convertEntries(const TCarmenLog& log, const TScanStatistics& stats, const TCarmenClock& clock,
					const TCarmenRangeLimits& limits, const TCarmenLaserMounts& mounts, const std::string& format,
					TCarmenImportReport& report)
{
	const auto sink = detail::makeCarmenRawlogSink(format, report.rawlogFile);
	CCarmenConverter converter(clock, limits, mounts, *sink);
	try
	{
		const double headerTime_s = clock.t_s.empty() ? 0.0 : clock.t_s.front();
		sink->write(makeComment("CARMEN_IMPORT", headerText(report, stats), headerTime_s));
		for (const auto& entry : log.entries) converter.add(entry);
	}
	catch (const std::exception& e)
	{
		sink->close();
		writeTumKeepingFirstError(report.tumFile, converter.reference());
		throw std::runtime_error(std::string(e.what()) + " (" + writtenSoFar(converter, report.rawlogFile, report.tumFile) + ")");
	}
	sink->close();
	hslam::common::writeTumFile(report.tumFile, converter.reference());
	converter.fillReport(report);
	if (log.fatalError)
		throw std::runtime_error(*log.fatalError + " (" + writtenSoFar(converter, report.rawlogFile, report.tumFile) + ")");
}
}  // namespace

TCarmenImportReport convertCarmenLog(const std::string& inputLog, const std::string& outRawlog,
									 const std::string& outTum, const TCarmenImportOptions& options)
{
	checkOptions(options);
	const TCarmenLog log = readCarmenLog(inputLog, options.lenient);
	TCarmenImportReport report = reportFromLog(log, outRawlog, outTum);
	report.rawlogFormat = options.format;
	const TScanStatistics stats = scanStatistics(log);

	const TCarmenClock clock = selectCarmenClock(stats.stamps, options.clock, options.synthetic_period_s);
	report.clockUsed = clock.name;
	report.clockReason = clock.reason;
	if (clock.repairedStamps > 0)
		report.warnings.push_back(std::to_string(clock.repairedStamps) + " isolated bad scan timestamp(s) of the " + clock.name +
								  " clock repaired by interpolation (see clock:)");

	const auto laserMax_m = paramLaserMax(log, report.warnings);
	const TCarmenRangeLimits limits = deriveCarmenRangeLimits(stats.maxima_m, laserMax_m, options.max_range_m);
	report.maxRange_m = limits.maxRange_m;
	report.noReturn_m = limits.noReturn_m;
	report.rangeLimitsReason = limits.reason;
	report.rangeOutlierScans = limits.outlierScans;
	if (limits.outlierScans > 0)
		report.warnings.push_back(std::to_string(limits.outlierScans) + " scan(s) have ranges above the no-return value " +
								  formatNumber(limits.maxRange_m) + " m (largest " + formatNumber(limits.largestOutlier_m) +
								  " m): those beams are marked invalid");

	const TCarmenLaserMounts mounts = carmenLaserMounts(log.params, log.path);
	noteLaserOffsets(mounts, report.warnings);

	convertEntries(log, stats, clock, limits, mounts, options.format, report);
	return report;
}

}  // namespace hslam::io
