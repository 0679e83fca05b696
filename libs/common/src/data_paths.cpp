#include <hslam/common/data_paths.h>

#include <system_error>

namespace hslam::common
{
std::filesystem::path executableDir()
{
	std::error_code error;
	const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
	if (error) return std::filesystem::current_path();
	return exe.parent_path();
}

std::filesystem::path dataDir()
{
	const auto dir = executableDir().parent_path() / "share" / "hslam";
	std::error_code error;
	const auto canonical = std::filesystem::weakly_canonical(dir, error);
	return error ? dir : canonical;
}

std::string defaultConfigFile() { return (dataDir() / "config_ini" / "hslam-default.ini").string(); }

std::string resolveDataFile(const std::string& path)
{
	const std::filesystem::path given(path);
	if (path.empty() || given.is_absolute() || std::filesystem::exists(given)) return path;
	const auto shipped = dataDir() / given;
	return std::filesystem::exists(shipped) ? shipped.string() : path;
}
}  // namespace hslam::common
