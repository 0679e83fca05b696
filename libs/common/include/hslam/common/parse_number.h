/* hslam: strict text-to-number conversion.
 * std::atof("abc") silently gives 0; these functions refuse anything that is
 * not entirely a finite number, so a typo in an INI or log file is reported
 * instead of becoming a zero. */
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace hslam::common
{
/** Parses a whole string as a finite double; nullopt on any leftover
 * character, empty input, NaN or infinity. */
std::optional<double> tryParseDouble(std::string_view text);

/** Parses a whole string as a (decimal) integer; nullopt on failure. */
std::optional<long long> tryParseInteger(std::string_view text);

/** Parses "1/0/true/false/yes/no/on/off" (any case); nullopt otherwise. */
std::optional<bool> tryParseBool(std::string_view text);

/** Removes leading/trailing blanks. */
std::string trim(std::string_view text);

}  // namespace hslam::common
