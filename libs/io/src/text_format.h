/* hslam io (internal): number formatting for messages and reports. */
#pragma once

#include <sstream>
#include <string>

namespace hslam::io::detail
{
/** Shortest-looking text of a number with up to `digits` significant digits. */
inline std::string formatNumber(double value, int digits = 10)
{
	std::ostringstream os;
	os.precision(digits);
	os << value;
	return os.str();
}
}  // namespace hslam::io::detail
