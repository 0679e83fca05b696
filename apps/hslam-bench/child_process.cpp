#include "child_process.h"

#include <hslam/slam/CMappingPipeline.h>
#include <hslam/slam/mapping_config.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace hslam::bench
{
std::string shellQuote(const std::string& s)
{
	std::string q = "'";
	for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
	return q + "'";
}

TProcessConfig TProcessConfig::checked(const std::string& ini, const std::vector<std::string>& overrides)
{
	TProcessConfig c{std::filesystem::absolute(ini).string(), overrides};
	if (!std::filesystem::exists(c.ini)) throw std::runtime_error(c.ini + " not found");
	// what hslam-process reads first: the file (naming its line), the
	// sections, then every stage's keys and ranges as the pipeline loads them
	const slam::CMappingPipeline pipeline(slam::TMappingConfig::fromConfig(c.ini, overrides).ini);
	return c;
}

std::string TProcessConfig::arguments() const
{
	std::string a = " -c " + shellQuote(ini);
	for (const auto& o : overrides) a += " --set " + shellQuote(o);
	return a;
}

double childCpuSeconds(const std::string& command, const std::string& logFile)
{
	return runTimedChild(command, logFile).cpu_s;
}

TChildTimes runTimedChild(const std::string& command, const std::string& logFile)
{
	const auto cpu = [] {
		rusage u{};
		getrusage(RUSAGE_CHILDREN, &u);
		return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
	};
	const double before = cpu();
	const auto start = std::chrono::steady_clock::now();
	const int status = std::system((command + " </dev/null >" + shellQuote(logFile) + " 2>&1").c_str());
	if (status != 0) throw std::runtime_error("command failed (status " + std::to_string(status) + "): " + command +
											  " (see " + logFile + ")");
	const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	return {cpu() - before, wall_s};
}

}  // namespace hslam::bench
