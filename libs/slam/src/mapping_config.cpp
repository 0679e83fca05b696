#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/features/CLineExtractor.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/slam/CScanMatchingPoseEstimator.h>
#include <hslam/slam/mapping_config.h>

namespace hslam::slam
{
namespace
{
/** The sections the chosen methods do not read still get their keys and
 * values checked: the other line extractors, and the scan-matching
 * sections when [pose_estimation] method = odometry. */
void checkSectionsOfOtherMethods(const mrpt::config::CConfigFileBase& cfg)
{
	const auto pose = common::loadedOptions<TPoseEstimationOptions>(cfg, "pose_estimation");
	const auto chosen = common::loadedOptions<TLineExtractionChoice>(cfg, "line_extraction").method;
	for (const auto& method : features::lineExtractorMethods())
		if (method != chosen) features::createLineExtractor(method, cfg, features::lineExtractorSection(method));
	if (pose.method == "odometry")
	{
		TPoseEstimationOptions scanMatching = pose;
		scanMatching.method = "lines+icp";
		common::CStageTimer timer;
		CScanMatchingPoseEstimator check(scanMatching, cfg, timer);
	}
}
}  // namespace

std::vector<std::string> TMappingConfig::knownSections()
{
	auto sections = CMappingPipeline::sections();
	sections.push_back("output");
	return sections;
}

std::vector<common::TPathKey> TMappingConfig::pathKeys()
{
	return {{"dynamic_objects", "classifier_model"}, {"vision", "rotation_model_file"}};
}

TMappingConfig TMappingConfig::fromConfig(const std::string& iniFile, const std::vector<std::string>& overrides)
{
	TMappingConfig config;
	config.ini = common::loadConfigWithOverrides(iniFile, overrides, pathKeys());
	common::checkKnownSectionsInFile(config.ini, knownSections(), iniFile);
	checkSectionsOfOtherMethods(config.ini);
	common::loadOptions(config.output, config.ini, "output");
	return config;
}

}  // namespace hslam::slam
