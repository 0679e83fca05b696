/* hslam: splitting one line of a CSV file. */
#pragma once

#include <string>
#include <vector>

namespace hslam::io
{
/** The fields of one CSV line: split at commas outside double quotes, quotes
 * removed, carriage returns dropped. An empty line is one empty field. */
std::vector<std::string> splitCsvLine(const std::string& line);

}  // namespace hslam::io
