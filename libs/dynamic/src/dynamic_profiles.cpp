#include <hslam/common/config_overrides.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/dynamic/dynamic_profiles.h>

namespace hslam::dynamic
{
CDynamicObjectFilter::TOptions loadDynamicOptions(const std::vector<std::string>& iniFiles)
{
	CDynamicObjectFilter::TOptions options;
	for (const auto& file : iniFiles)
	{
		if (file.empty()) continue;
		const auto cfg = common::loadConfigWithOverrides(file, {}, {{"dynamic_objects", "classifier_model"}});
		try
		{
			common::loadOptions(options, cfg, "dynamic_objects");
		}
		catch (const common::config_error& e)
		{
			throw common::config_error(file + ": " + e.what());
		}
	}
	return options;
}

CLegClassifier::TTrainOptions loadLegTrainOptions(const std::string& configFile)
{
	CLegClassifier::TTrainOptions options;
	if (!configFile.empty())
	{
		const auto cfg = common::loadIniFile(configFile);
		try
		{
			common::loadOptions(options, cfg, "leg_classifier");
		}
		catch (const common::config_error& e)
		{
			throw common::config_error(configFile + ": " + e.what());
		}
	}
	return options;
}

}  // namespace hslam::dynamic
