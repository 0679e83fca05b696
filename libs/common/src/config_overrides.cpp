#include <hslam/common/config_overrides.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>

#include <filesystem>

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

namespace
{
/** Makes the value of `key` absolute, relative to `base`. */
void makeAbsolute(mrpt::config::CConfigFileMemory& cfg, const TPathKey& key, const std::filesystem::path& base)
{
	if (!cfg.keyExists(key.section, key.key)) return;
	const std::string value = stripInlineComment(cfg.read_string(key.section, key.key, "", false));
	if (value.empty()) return;
	const std::filesystem::path path(value);
	if (path.is_absolute()) return;
	cfg.write(key.section, key.key, std::filesystem::absolute(base / path).lexically_normal().string());
}
}  // namespace

mrpt::config::CConfigFileMemory loadConfigWithOverrides(const std::string& iniFile,
														const std::vector<std::string>& overrides,
														const std::vector<TPathKey>& pathKeys)
{
	mrpt::config::CConfigFileMemory cfg;
	if (!iniFile.empty())
	{
		cfg = loadIniFile(iniFile);
		for (const auto& key : pathKeys) makeAbsolute(cfg, key, std::filesystem::path(iniFile).parent_path());
	}
	for (const auto& text : overrides)
	{
		const auto o = parseConfigOverride(text);
		cfg.write(o.section, o.key, o.value);
		for (const auto& key : pathKeys)
			if (key.section == o.section && key.key == o.key) makeAbsolute(cfg, key, std::filesystem::current_path());
	}
	return cfg;
}

}  // namespace hslam::common
