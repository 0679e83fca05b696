#include <hslam/common/json_text.h>

#include <cmath>
#include <cstdio>

namespace hslam::common
{
std::string jsonNumber(double value, const char* printfFormat)
{
	if (!std::isfinite(value)) return "null";
	char text[64];
	std::snprintf(text, sizeof(text), printfFormat, value);
	return text;
}

std::string jsonString(const std::string& value)
{
	std::string out = "\"";
	for (const char c : value)
	{
		if (c == '"' || c == '\\') out += std::string("\\") + c;
		else if (static_cast<unsigned char>(c) < 0x20)
		{
			char escaped[8];
			std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned>(c));
			out += escaped;
		}
		else out += c;
	}
	return out + "\"";
}

std::string jsonStringArray(const std::vector<std::string>& values)
{
	std::string out = "[";
	for (size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + jsonString(values[i]);
	return out + "]";
}
}  // namespace hslam::common
