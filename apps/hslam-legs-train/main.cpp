/* hslam-legs-train: trains the learned leg classifier (CLegClassifier, a
 * random forest over leg_features.h) on labelled laser data laid out like
 * ../shared/datasets/legs/ and writes the model that [dynamic_objects]
 * classifier_model loads. Segmentation and range limit come from the
 * [dynamic_objects] keys of --config (default: the Hokuyo legs profile
 * config_ini/hslam-legs-hokuyo.ini); forest settings from its
 * [leg_classifier] section.
 * Cross-validated scores of the whole filter: hslam-bench legs. */
#include <hslam/common/command_line.h>
#include <hslam/common/version.h>
#include <hslam/dynamic/dynamic_profiles.h>
#include <hslam/benchdata/leg_training.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <numeric>

namespace
{
void printImportance(const hslam::dynamic::CLegClassifier& model)
{
	const auto importance = model.featureImportance();
	std::cout << "feature importance:\n";
	for (size_t k = 0; k < importance.size(); ++k)
		std::cout << "  " << std::left << std::setw(24) << hslam::dynamic::legFeatureName(k) << std::right
				  << std::fixed << std::setprecision(3) << importance[k] << "\n";
}
}  // namespace

int main(int argc, char** argv)
{
	using namespace hslam::dynamic;
	using namespace hslam::benchdata;
	try
	{
		TCLAP::CmdLine cmd("Trains the leg classifier on labelled laser data and writes the model file.", ' ', hslam::common::versionText());
		TCLAP::ValueArg<std::string> dataArg("", "data", "Folder laid out like ../shared/datasets/legs (default: ../shared/datasets/legs)", false,
											 "../shared/datasets/legs", "DIR", cmd);
		TCLAP::ValueArg<std::string> outArg("o", "out", "Model file to write (.yml, .yml.gz) (required)", true, "", "MODEL", cmd);
		TCLAP::ValueArg<std::string> configArg(
			"c", "config", "INI: [dynamic_objects] gives the segmentation, [leg_classifier] the forest",
			false, "config_ini/hslam-legs-hokuyo.ini", "INI", cmd);
		if (!cmd.parse(argc, argv)) return hslam::common::exitCodeAfterParseStop(argc, argv);

		const auto options = loadDynamicOptions({configArg.getValue()});
		const auto training = loadLegTrainOptions(configArg.getValue());
		std::cout << "reading " << dataArg.getValue() << " ..." << std::endl;
		const auto parts = loadLegDataset(dataArg.getValue());
		std::vector<size_t> all(parts.size());
		std::iota(all.begin(), all.end(), size_t{0});
		for (const auto& p : parts)
			std::cout << "  " << std::left << std::setw(26) << p.name << std::right << std::setw(6) << p.scans.size()
					  << " scans" << (p.has_people ? "  (annotated legs)" : "  (no people)") << "\n";
		std::cout << "clustering (" << options.detector.clustering.cluster_distance_m << " m, >= "
				  << options.detector.clustering.min_points << " points, centroid < " << options.detector.max_range_m
				  << " m) ..." << std::endl;
		const auto set = legTrainingSet(parts, all, options.detector);
		std::cout << "  " << set.legs() << " legs, " << set.features.size() - set.legs() << " non-legs\n"
				  << "training " << training.trees << " trees (depth <= " << training.max_depth << ") ..." << std::endl;
		const auto t0 = std::chrono::steady_clock::now();
		CLegClassifier model;
		model.train(set.features, set.is_leg, training);
		std::cout << "  " << std::setprecision(1) << std::fixed
				  << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
		printImportance(model);
		model.save(outArg.getValue());
		// The written file must give the same answers as the model in memory.
		const auto reloaded = CLegClassifier::load(outArg.getValue());
		for (size_t i = 0; i < set.features.size(); i += 97)
			if (reloaded.probability(set.features[i]) != model.probability(set.features[i]))
				throw std::runtime_error(outArg.getValue() + ": the reloaded model disagrees with the trained one");
		std::cout << "model written to " << outArg.getValue()
				  << "\nuse it with [dynamic_objects] classifier_model = " << outArg.getValue() << "\n";
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-legs-train: error: " << e.what() << "\n";
		return 1;
	}
}
