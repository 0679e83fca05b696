#include <hslam/common/parse_number.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace hslam::common
{
std::string trim(std::string_view text)
{
	const auto isBlank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
	while (!text.empty() && isBlank(text.front())) text.remove_prefix(1);
	while (!text.empty() && isBlank(text.back())) text.remove_suffix(1);
	return std::string(text);
}

std::optional<double> tryParseDouble(std::string_view text)
{
	const std::string s = trim(text);
	if (s.empty()) return std::nullopt;
	char* end = nullptr;
	errno = 0;
	const double value = std::strtod(s.c_str(), &end);
	if (end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(value))
		return std::nullopt;
	return value;
}

std::optional<long long> tryParseInteger(std::string_view text)
{
	const std::string s = trim(text);
	if (s.empty()) return std::nullopt;
	char* end = nullptr;
	errno = 0;
	const long long value = std::strtoll(s.c_str(), &end, 10);
	if (end != s.c_str() + s.size() || errno == ERANGE) return std::nullopt;
	return value;
}

std::optional<bool> tryParseBool(std::string_view text)
{
	std::string s = trim(text);
	std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
	if (s == "1" || s == "true" || s == "yes" || s == "on") return true;
	if (s == "0" || s == "false" || s == "no" || s == "off") return false;
	return std::nullopt;
}

}  // namespace hslam::common
