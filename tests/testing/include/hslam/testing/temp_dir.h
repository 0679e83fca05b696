/* hslam tests: a fresh temporary folder per test, removed afterwards. */
#pragma once

#include <filesystem>
#include <random>
#include <string>

namespace hslam::testing
{
class CTempDir
{
   public:
	CTempDir()
	{
		std::random_device rd;
		m_path = std::filesystem::temp_directory_path() / ("hslam_test_" + std::to_string(rd()) + std::to_string(rd()));
		std::filesystem::create_directories(m_path);
	}
	~CTempDir()
	{
		std::error_code ec;
		std::filesystem::remove_all(m_path, ec);
	}
	CTempDir(const CTempDir&) = delete;
	CTempDir& operator=(const CTempDir&) = delete;

	const std::filesystem::path& path() const { return m_path; }
	std::string file(const std::string& name) const { return (m_path / name).string(); }

   private:
	std::filesystem::path m_path;
};

/** Runs a shell command, returns its exit status (0 = success). */
int runCommand(const std::string& command);

}  // namespace hslam::testing

#include <cstdlib>
#include <sys/wait.h>
inline int hslam::testing::runCommand(const std::string& command)
{
	const int status = std::system(command.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}
