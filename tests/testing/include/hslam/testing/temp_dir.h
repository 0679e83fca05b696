/* hslam tests: a fresh temporary folder per test, removed afterwards (kept,
 * and its path printed, when HSLAM_KEEP_TEST_DIRS is set: to look at what a
 * failing integration test wrote). */
#pragma once

#include <cstdio>
#include <cstdlib>
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
		if (std::getenv("HSLAM_KEEP_TEST_DIRS"))
		{
			std::printf("test folder kept: %s\n", m_path.c_str());
			return;
		}
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

/** Exit status and the standard output + standard error of a command. */
struct TCommandOutput
{
	int exitCode = -1;
	std::string out;
};
/** Runs a shell command, capturing its standard output and standard error. */
TCommandOutput runCapturingOutput(const std::string& command);

/** The whole text of a file ("" if it cannot be read). */
std::string readTextFile(const std::string& path);

}  // namespace hslam::testing

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <sys/wait.h>
inline int hslam::testing::runCommand(const std::string& command)
{
	const int status = std::system(command.c_str());
	return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

inline hslam::testing::TCommandOutput hslam::testing::runCapturingOutput(const std::string& command)
{
	TCommandOutput r;
	std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>&1").c_str(), "r"), pclose);
	if (!pipe) return r;
	std::array<char, 4096> buffer{};
	while (fgets(buffer.data(), buffer.size(), pipe.get())) r.out += buffer.data();
	const int status = pclose(pipe.release());
	r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
	return r;
}

inline std::string hslam::testing::readTextFile(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream text;
	text << in.rdbuf();
	return text.str();
}
