#include <hslam/common/options_io.h>
#include <hslam/dynamic/dynamic_profiles.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <filesystem>

namespace hslam::dynamic
{
namespace
{
void requireFile(const std::string& path)
{
	if (!std::filesystem::is_regular_file(path)) throw common::config_error(path + ": no such file");
}
}  // namespace

CDynamicObjectFilter::TOptions loadDynamicOptions(const std::string& profileIni, const std::string& configFile)
{
	CDynamicObjectFilter::TOptions options;
	mrpt::config::CConfigFileMemory profile(profileIni);
	common::loadOptions(options, profile, "dynamic_objects");
	if (!configFile.empty())
	{
		requireFile(configFile);
		mrpt::config::CConfigFile cfg(configFile);
		common::loadOptions(options, cfg, "dynamic_objects");
	}
	return options;
}

CLegClassifier::TTrainOptions loadLegTrainOptions(const std::string& configFile)
{
	CLegClassifier::TTrainOptions options;
	if (!configFile.empty())
	{
		requireFile(configFile);
		mrpt::config::CConfigFile cfg(configFile);
		common::loadOptions(options, cfg, "leg_classifier");
	}
	return options;
}

}  // namespace hslam::dynamic
