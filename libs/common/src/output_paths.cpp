#include <hslam/common/output_paths.h>

#include <filesystem>

namespace hslam::common
{
namespace
{
namespace fs = std::filesystem;

/** Same file: equivalent() for existing files (symlinks, hard links), else
 * the same normalised absolute path. */
bool sameFile(const std::string& a, const std::string& b)
{
	std::error_code ec;
	if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
	return fs::weakly_canonical(fs::absolute(a), ec) == fs::weakly_canonical(fs::absolute(b), ec);
}
}  // namespace

void refuseOutputOverInput(const std::string& output, const std::string& what, const std::vector<std::string>& inputs)
{
	for (const auto& in : inputs)
		if (!in.empty() && !output.empty() && sameFile(output, in))
			throw output_path_error(what + " '" + printableName(output) + "' is the input '" + printableName(in) +
									"': refusing to overwrite an input");
}

void refuseSameOutputs(const std::string& a, const std::string& b)
{
	if (!a.empty() && sameFile(a, b))
		throw output_path_error("two outputs name the same file '" + printableName(a) + "'");
}

std::string printableName(const std::string& text)
{
	std::string out = text;
	for (char& c : out)
	{
		const auto u = static_cast<unsigned char>(c);
		if (u < 0x20 || u == 0x7f) c = '?';
	}
	return out;
}

}  // namespace hslam::common
