/* hslam: text form of a CARMEN import report (the app prints it). */
#include <hslam/io/carmen_import.h>

#include <sstream>

#include "text_format.h"

namespace hslam::io
{
namespace
{
void printCounts(std::ostringstream& os, const std::string& title, const std::map<std::string, size_t>& counts)
{
	os << title << ":";
	if (counts.empty()) os << " none";
	for (const auto& [name, count] : counts) os << " " << name << "=" << count;
	os << "\n";
}
}  // namespace

std::string formatCarmenImportReport(const TCarmenImportReport& r)
{
	std::ostringstream os;
	os << "input:  " << r.inputFile << "\n"
	   << "output: " << r.rawlogFile << " (rawlog, " << r.rawlogFormat << "), " << r.tumFile << " (TUM reference)\n";
	printCounts(os, "messages parsed", r.parsedMessages);
	printCounts(os, "messages skipped", r.skippedMessages);
	os << "malformed lines skipped: " << r.malformedLinesSkipped << "\n";
	for (const auto& example : r.malformedExamples) os << "  " << example << "\n";
	os << "scans written: " << r.frontScans << " front, " << r.rearScans << " rear, " << r.rawScans << " raw\n"
	   << "reference poses: " << r.referencePoses << "\n"
	   << "odometry: " << r.odometryObservations << " observations, " << r.odometryGaps << " gaps, "
	   << r.odometryAnchors << " anchor lines\n"
	   << "clock: " << r.clockUsed << " (" << r.clockReason << ")\n"
	   << "invalid ranges: "
	   << (r.noReturn_m ? ">= " + detail::formatNumber(*r.noReturn_m) + " m and <= 0" : std::string("<= 0 only"))
	   << "; maxRange " << detail::formatNumber(r.maxRange_m) << " m (" << r.rangeLimitsReason << ")\n"
	   << "scans with outlier ranges above the no-return value: " << r.rangeOutlierScans << "\n";
	os << "warnings: " << r.warnings.size() << "\n";
	for (const auto& warning : r.warnings) os << "  " << warning << "\n";
	return os.str();
}

}  // namespace hslam::io
