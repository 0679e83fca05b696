#include <hslam/benchdata/leg_training.h>

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace hslam::benchdata
{
size_t TLegTrainingSet::legs() const { return static_cast<size_t>(std::count(is_leg.begin(), is_leg.end(), true)); }

TLegTrainingSet legTrainingSet(const std::vector<TLegDataPart>& parts, const std::vector<size_t>& use,
							   const dynamic::CLegDetector::TOptions& detector)
{
	// The detector's own segmentation (its clustering range is derived from max_range_m).
	const dynamic::TClusterOptions clustering = dynamic::CLegDetector(detector, nullptr).options().clustering;
	TLegTrainingSet set;
	for (size_t i : use)
		for (const auto& c : labelledClusters(parts.at(i), clustering, detector.max_range_m))
		{
			if (c.label == TLabelledCluster::ELabel::unlabelled) continue;
			set.features.push_back(c.features);
			set.is_leg.push_back(c.label == TLabelledCluster::ELabel::leg);
		}
	return set;
}

std::vector<int> legCrossValidationFolds(const std::vector<TLegDataPart>& parts, int folds)
{
	const auto positives = static_cast<int>(
		std::count_if(parts.begin(), parts.end(), [](const TLegDataPart& p) { return p.has_people; }));
	const int negatives = static_cast<int>(parts.size()) - positives;
	if (positives == 0 || negatives == 0)
		throw std::runtime_error("leg classifier: needs recordings with people (positive_*_extracted) and without (negative_*); found " +
								 std::to_string(positives) + " and " + std::to_string(negatives));
	const int k = std::max(1, std::min({folds, positives, negatives}));
	std::vector<int> fold(parts.size());
	int pos = 0, neg = 0;
	for (size_t i = 0; i < parts.size(); ++i) fold[i] = (parts[i].has_people ? pos++ : neg++) % k;
	return fold;
}

TFoldClassifiers trainFoldClassifiers(const std::vector<TLegDataPart>& parts, const dynamic::CLegDetector::TOptions& detector,
									  const dynamic::CLegClassifier::TTrainOptions& training)
{
	TFoldClassifiers out;
	out.fold_of_part = legCrossValidationFolds(parts);
	const int k = *std::max_element(out.fold_of_part.begin(), out.fold_of_part.end()) + 1;
	for (int f = 0; f < k; ++f)
	{
		std::vector<size_t> trainParts;
		std::string members;
		for (size_t i = 0; i < parts.size(); ++i)
			if (out.fold_of_part[i] != f)
				trainParts.push_back(i);
			else
				members += (members.empty() ? "" : " + ") + parts[i].name;
		out.description += (f ? "; fold " : "fold ") + std::to_string(f + 1) + ": " + members;
		// With one fold there is nothing held out: train on everything.
		if (k == 1)
		{
			trainParts.resize(parts.size());
			std::iota(trainParts.begin(), trainParts.end(), size_t{0});
		}
		const auto set = legTrainingSet(parts, trainParts, detector);
		auto model = std::make_shared<dynamic::CLegClassifier>();
		model->train(set.features, set.is_leg, training);
		out.models.push_back(model);
	}
	return out;
}

std::shared_ptr<const dynamic::CLegClassifier> trainOnAll(const std::vector<TLegDataPart>& parts,
												 const dynamic::CLegDetector::TOptions& detector,
												 const dynamic::CLegClassifier::TTrainOptions& training)
{
	std::vector<size_t> all(parts.size());
	std::iota(all.begin(), all.end(), size_t{0});
	const auto set = legTrainingSet(parts, all, detector);
	auto model = std::make_shared<dynamic::CLegClassifier>();
	model->train(set.features, set.is_leg, training);
	return model;
}

}  // namespace hslam::benchdata
