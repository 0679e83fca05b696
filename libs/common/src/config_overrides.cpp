#include <hslam/common/config_overrides.h>
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace hslam::common
{
TConfigOverride parseConfigOverride(const std::string& text)
{
	const auto eq = text.find('=');
	const auto dot = text.find('.');
	if (eq == std::string::npos || dot == std::string::npos || dot > eq || dot == 0 || dot + 1 == eq)
		throw config_error("--set '" + text + "': expected SECTION.KEY=VALUE");
	return {trim(text.substr(0, dot)), trim(text.substr(dot + 1, eq - dot - 1)), trim(text.substr(eq + 1))};
}

mrpt::config::CConfigFileMemory loadConfigWithOverrides(
	const std::string& iniFile, const std::vector<std::string>& overrides)
{
	mrpt::config::CConfigFileMemory cfg;
	if (!iniFile.empty())
	{
		std::ifstream in(iniFile);
		if (!in) throw config_error(iniFile + ": cannot open configuration file");
		std::stringstream contents;
		contents << in.rdbuf();
		cfg.setContent(contents.str());
	}
	for (const auto& text : overrides)
	{
		const auto o = parseConfigOverride(text);
		cfg.write(o.section, o.key, o.value);
	}
	return cfg;
}

void resolvePathNextToIni(mrpt::config::CConfigFileMemory& cfg, const std::string& section, const std::string& key,
						  const std::string& iniFile)
{
	const std::string value = cfg.read_string(section, key, "");
	if (value.empty() || iniFile.empty() || std::filesystem::path(value).is_absolute()) return;
	const auto besideIni = std::filesystem::path(iniFile).parent_path() / value;
	if (std::filesystem::exists(besideIni)) cfg.write(section, key, besideIni.string());
}

}  // namespace hslam::common
