/* hslam: a whole CARMEN log parsed into memory (first pass of the importer).
 * CARMEN logs are small (the 13 measured real logs: < 20 k lines, a few MB),
 * and the importer needs statistics over all scans (clock, no-return value)
 * before it can write anything. */
#pragma once

#include <hslam/io/carmen_messages.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hslam::io
{
struct TCarmenLogEntry
{
	size_t line = 0;  //!< 1-based line number in the file
	TCarmenMessage message;
};

struct TCarmenParamValue
{
	std::string value;
	size_t line = 0;
};

struct TCarmenLog
{
	std::string path;
	/** Lasers, ODOM and PARAM in file order (skipped messages are only counted). */
	std::vector<TCarmenLogEntry> entries;
	std::map<std::string, size_t> parsedCounts;  //!< per message name
	std::map<std::string, size_t> skippedCounts;  //!< per message name ("#" = comments)
	std::map<std::string, TCarmenParamValue> params;  //!< last value of each PARAM
	size_t malformedLines = 0;  //!< lenient mode: lines skipped as malformed
	std::vector<std::string> malformedExamples;  //!< the first few, "file:line: what"
	/** Strict mode: the first malformed line ("file:line: what"); reading
	 * stopped there and `entries` holds what came before it. A corrupt or
	 * truncated gzip stream also ends reading (as a malformed line in lenient
	 * mode). */
	std::optional<std::string> fatalError;
};

/** Most malformed-line messages kept in a TCarmenLog / import report. */
constexpr size_t kMaxMalformedExamples = 10;

/** Reads and parses a plain or gzip CARMEN log. Throws std::runtime_error
 * only if the file cannot be opened; malformed content is reported in the
 * result (fatalError, or malformedLines when `lenient`). */
TCarmenLog readCarmenLog(const std::string& path, bool lenient);

}  // namespace hslam::io
