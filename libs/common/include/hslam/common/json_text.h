/* hslam: the small pieces of JSON text the apps write (summary.json and
 * evaluation files): numbers (non-finite -> null) and escaped strings. */
#pragma once

#include <string>
#include <vector>

namespace hslam::common
{
/** A number in JSON; NaN and infinities become null. */
std::string jsonNumber(double value, const char* printfFormat = "%.10g");

/** A JSON string literal with quotes, backslashes and control characters escaped. */
std::string jsonString(const std::string& value);

/** A JSON array of strings. */
std::string jsonStringArray(const std::vector<std::string>& values);
}  // namespace hslam::common
