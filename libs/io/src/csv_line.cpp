#include <hslam/io/csv_line.h>

namespace hslam::io
{
std::vector<std::string> splitCsvLine(const std::string& line)
{
	std::vector<std::string> out(1);
	bool quoted = false;
	for (char c : line)
	{
		if (c == '"')
			quoted = !quoted;
		else if (c == ',' && !quoted)
			out.emplace_back();
		else if (c != '\r')
			out.back() += c;
	}
	return out;
}

}  // namespace hslam::io
