/* hslam-vision-train: trains the thesis's learned rotation-flow model
 * (4.8.2 ii, figure 176, appendix I.1: a 3-5-2 tanh network, inputs x/100,
 * y/100 from the image centre and the robot rotation in degrees, outputs the
 * flow u, v) on image pairs taken while the robot turns on the spot, from a
 * rawlog with CObservationImage + odometry (e.g. rawlog_samples/camera from
 * hslam-simulate: it turns left and back first) and/or from plane-warp turns
 * of the camera in [camera] of --config (vision::scenarioPair). Every
 * held_out_every-th pair is held out. Writes the model that
 *     [vision] rotation_model = learned
 *     [vision] rotation_model_file = MODEL
 * loads (vision::CLearnedRotationFlow YAML), and prints the training and
 * held-out residual RMS (measured minus predicted flow, px) next to the
 * analytic model's on the same held-out tracks. */
#include "training_pairs.h"

#include <hslam/common/command_line.h>
#include <hslam/common/version.h>
#include <hslam/vision/synthetic_evaluation.h>

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace hslam;
using namespace hslam::vision_train;

namespace
{
using TSamples = std::vector<vision::TRotationSample>;

/** Adds `more` to `all` (images of one size only). */
void merge(TPairSet& all, TPairSet&& more)
{
	if (all.images == 0)
	{
		all = std::move(more);
		return;
	}
	if (more.width != all.width || more.height != all.height)
		throw std::runtime_error("synthetic pairs are " + std::to_string(more.width) + " x " +
								 std::to_string(more.height) + ", the rawlog's images " + std::to_string(all.width) +
								 " x " + std::to_string(all.height) + " ([camera] width_px / height_px)");
	if (all.checked.empty()) all.checked = all.pairs;  // the rawlog's tracks as they are
	for (auto& p : more.pairs) all.pairs.push_back(std::move(p));
	for (auto& p : more.checked) all.checked.push_back(std::move(p));
	all.tracker_failures += more.tracker_failures;
	all.images += more.images;
}

/** Every every-th pair is held out (its truth-checked tracks when there are). */
void split(const TPairSet& set, int every, TSamples& train, TSamples& heldOut)
{
	for (size_t i = 0; i < set.pairs.size(); ++i)
	{
		const bool held = i % static_cast<size_t>(every) == static_cast<size_t>(every) - 1;
		const auto& from = held && !set.checked.empty() ? set.checked[i] : set.pairs[i];
		(held ? heldOut : train).insert((held ? heldOut : train).end(), from.begin(), from.end());
	}
}

void writeModel(const vision::CLearnedRotationFlow& model, const std::string& path, const TSamples& check)
{
	{
		std::ofstream out(path);
		if (!(out << model.toYaml()) || !out.flush()) throw std::runtime_error(path + ": cannot write the model");
	}
	std::ifstream in(path);
	std::stringstream text;
	text << in.rdbuf();
	const auto reloaded = vision::CLearnedRotationFlow::fromYaml(text.str());
	for (size_t i = 0; i < check.size(); i += 97)
		if (cv::norm(reloaded.predict({check[i].p0}, check[i].robot_yaw_rad)[0] -
					 model.predict({check[i].p0}, check[i].robot_yaw_rad)[0]) > 1e-3)
			throw std::runtime_error(path + ": the reloaded model disagrees with the trained one");
}

void report(const TPairSet& set, const vision::CLearnedRotationFlow& model, const TSamples& trainUsed,
			const TSamples& heldOut, const vision::TRotationTrainingOptions& o)
{
	const TSamples heldOutKept = vision::selectTrainingSamples(heldOut, o);
	const vision::CAnalyticRotationFlow analytic(set.camera);
	std::cout << std::fixed << std::setprecision(3) << "residual RMS (px; measured minus predicted flow):\n"
			  << "  training, after the outlier rule   " << vision::rotationResidualRms(model, trainUsed) << "  ("
			  << trainUsed.size() << " tracks)\n"
			  << "  held out, after the outlier rule   " << vision::rotationResidualRms(model, heldOutKept)
			  << "  (analytic model " << vision::rotationResidualRms(analytic, heldOutKept) << ", "
			  << heldOutKept.size() << " tracks)\n"
			  << "  held out, before the outlier rule  " << vision::rotationResidualRms(model, heldOut)
			  << "  (analytic model " << vision::rotationResidualRms(analytic, heldOut) << ", " << heldOut.size()
			  << " tracks)\n"
			  << "training_residual_px_rms=" << vision::rotationResidualRms(model, trainUsed)
			  << "\nheldout_residual_px_rms=" << vision::rotationResidualRms(model, heldOutKept)
			  << "\nheldout_analytic_residual_px_rms=" << vision::rotationResidualRms(analytic, heldOutKept) << "\n";
}

TPairSet collectPairs(const std::string& rawlog, int synthetic, const TLoadedTrainConfig& cfg)
{
	TPairSet set;
	if (!rawlog.empty())
	{
		std::cout << "reading " << rawlog << " ..." << std::endl;
		set = pairsFromRawlog(rawlog, cfg.train);
		std::cout << "  " << set.images << " images " << set.width << " x " << set.height << ", " << set.pairs.size()
				  << " pairs turning >= " << cfg.train.min_turn_deg << " deg within " << cfg.train.max_travel_m
				  << " m, " << set.not_turning << " pairs left out\n";
	}
	if (synthetic > 0)
	{
		const auto camera = vision::mountedCamera(cfg.camera.intrinsics, cfg.camera.mount);
		std::cout << "tracking " << synthetic << " plane-warp turns (" << camera.intrinsics.ncols << " x "
				  << camera.intrinsics.nrows << ") ..." << std::endl;
		merge(set, syntheticPairs(camera, synthetic, static_cast<uint64_t>(cfg.train.network.seed)));
		std::cout << "  " << set.tracker_failures << " tracks farther than 2 px from the true motion (held-out "
				  << "figures leave them out; training keeps them)\n";
	}
	const size_t every = static_cast<size_t>(cfg.train.held_out_every);
	if (set.pairs.size() < every)
		throw std::runtime_error((rawlog.empty() ? std::string("--synthetic") : rawlog) + ": " +
								 std::to_string(set.pairs.size()) + " turning pairs, at least held_out_every = " +
								 std::to_string(every) + " are needed (one held out)");
	return set;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		TCLAP::CmdLine cmd("Trains the learned rotation-flow model (thesis 4.8.2 ii) and writes the model file.", ' ',
						   common::versionText());
		TCLAP::ValueArg<std::string> rawlogArg("r", "rawlog", "Rawlog with CObservationImage and odometry (pairs while the robot turns on the spot)",
											   false, "", "RAWLOG", cmd);
		TCLAP::ValueArg<int> syntheticArg("s", "synthetic", "Also N plane-warp turns of the [camera] of --config (default 0)", false, 0, "N", cmd);
		TCLAP::ValueArg<std::string> outArg("o", "out", "Model file to write (.yml) (required)", true, "", "MODEL", cmd);
		TCLAP::ValueArg<std::string> configArg("c", "config", "INI: [vision_train] (network, pair selection), [camera] for --synthetic (default: none, thesis values)",
											   false, "", "INI", cmd);
		if (!cmd.parse(argc, argv)) return common::exitCodeAfterParseStop(argc, argv);
		if (rawlogArg.getValue().empty() && syntheticArg.getValue() <= 0)
			throw std::runtime_error("nothing to train on: give --rawlog FILE and/or --synthetic N (N > 0)");

		const auto cfg = loadTrainConfig(configArg.getValue());
		const TPairSet set = collectPairs(rawlogArg.getValue(), syntheticArg.getValue(), cfg);
		TSamples train, heldOut;
		split(set, cfg.train.held_out_every, train, heldOut);
		const TSamples used = vision::selectTrainingSamples(train, cfg.train.network);
		std::cout << "training 3-" << cfg.train.network.hidden_neurons << "-2 on " << used.size() << " of "
				  << train.size() << " tracks (outlier rule), " << heldOut.size() << " held out ..." << std::endl;
		vision::CLearnedRotationFlow model;
		model.train(used, set.width, set.height, cfg.train.network);
		report(set, model, used, heldOut, cfg.train.network);
		writeModel(model, outArg.getValue(), used);
		std::cout << "model written to " << outArg.getValue() << "\nuse it with [vision] rotation_model = learned, "
				  << "rotation_model_file = " << outArg.getValue() << "\n";
		return 0;
	}
	catch (const std::exception& e)
	{
		std::cerr << "hslam-vision-train: error: " << e.what() << "\n";
		return 1;
	}
}
