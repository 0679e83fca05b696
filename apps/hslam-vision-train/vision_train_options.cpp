#include "vision_train_options.h"

#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>

namespace hslam::vision_train
{
TLoadedTrainConfig loadTrainConfig(const std::string& iniPath)
{
	TLoadedTrainConfig c;
	if (iniPath.empty()) return c;
	const auto cfg = common::loadIniFile(iniPath);
	try
	{
		common::loadOptions(c.train, cfg, "vision_train");
		if (cfg.sectionExists("camera")) common::loadOptions(c.camera, cfg, "camera");
	}
	catch (const common::config_error& e)
	{
		throw common::config_error(iniPath + ": " + e.what());
	}
	return c;
}

}  // namespace hslam::vision_train
