#include <hslam/dynamic/CLegClassifier.h>

#include <opencv2/core.hpp>
#include <opencv2/ml.hpp>

#include <filesystem>
#include <stdexcept>

namespace hslam::dynamic
{
struct CLegClassifier::TImpl
{
	cv::Ptr<cv::ml::RTrees> forest;
};

namespace
{
/** A 1 x N row viewing `f` (no copy: prediction runs per cluster per scan). */
cv::Mat rowOf(const TLegFeatures& f)
{
	return cv::Mat(1, static_cast<int>(kLegFeatureCount), CV_32F, const_cast<float*>(f.data()));
}
}  // namespace

CLegClassifier::CLegClassifier() : m_impl(std::make_unique<TImpl>()) {}
CLegClassifier::~CLegClassifier() = default;
CLegClassifier::CLegClassifier(CLegClassifier&&) noexcept = default;
CLegClassifier& CLegClassifier::operator=(CLegClassifier&&) noexcept = default;

void CLegClassifier::train(const std::vector<TLegFeatures>& features, const std::vector<bool>& isLeg,
						   const TTrainOptions& options)
{
	if (features.size() != isLeg.size()) throw std::invalid_argument("CLegClassifier::train: one label per sample");
	size_t positives = 0;
	for (bool b : isLeg) positives += b;
	if (positives == 0 || positives == isLeg.size())
		throw std::invalid_argument("CLegClassifier::train: needs legs and non-legs (" + std::to_string(positives) +
									" legs of " + std::to_string(isLeg.size()) + " samples)");
	cv::Mat samples(static_cast<int>(features.size()), static_cast<int>(kLegFeatureCount), CV_32F);
	cv::Mat labels(static_cast<int>(features.size()), 1, CV_32S);
	// Sample weights give the classes the prior mass (positive_prior, 1 -
	// positive_prior) however many samples each has (about 1 leg per 30
	// clusters in real data); mean weight 1.
	cv::Mat weights(static_cast<int>(features.size()), 1, CV_32F);
	const double n = static_cast<double>(features.size());
	const double legWeight = options.positive_prior * n / static_cast<double>(positives);
	const double otherWeight = (1 - options.positive_prior) * n / static_cast<double>(isLeg.size() - positives);
	for (size_t i = 0; i < features.size(); ++i)
	{
		rowOf(features[i]).copyTo(samples.row(static_cast<int>(i)));
		labels.at<int>(static_cast<int>(i)) = isLeg[i] ? 1 : 0;
		weights.at<float>(static_cast<int>(i)) = static_cast<float>(isLeg[i] ? legWeight : otherWeight);
	}
	auto forest = cv::ml::RTrees::create();
	forest->setMaxDepth(options.max_depth);
	forest->setMinSampleCount(options.min_sample_count);
	forest->setRegressionAccuracy(0);
	forest->setUseSurrogates(false);
	forest->setMaxCategories(2);
	forest->setCalculateVarImportance(true);
	forest->setActiveVarCount(options.active_features);
	forest->setTermCriteria(cv::TermCriteria(cv::TermCriteria::MAX_ITER, options.trees, 0));
	// OpenCV draws bootstrap samples from its thread's default generator.
	cv::theRNG().state = static_cast<uint64_t>(options.seed);
	forest->train(cv::ml::TrainData::create(samples, cv::ml::ROW_SAMPLE, labels, cv::noArray(), cv::noArray(), weights));
	m_impl->forest = forest;
}

bool CLegClassifier::trained() const { return m_impl->forest && m_impl->forest->isTrained(); }

int CLegClassifier::trees() const { return trained() ? static_cast<int>(m_impl->forest->getRoots().size()) : 0; }

double CLegClassifier::probability(const TLegFeatures& f) const
{
	if (!trained()) throw std::logic_error("CLegClassifier: no model trained or loaded");
	cv::Mat votes;
	m_impl->forest->getVotes(rowOf(f), votes, 0);
	// Row 0 holds the class labels, row 1 the vote counts of this sample.
	double leg = 0, total = 0;
	for (int c = 0; c < votes.cols; ++c)
	{
		total += votes.at<int>(1, c);
		if (votes.at<int>(0, c) == 1) leg += votes.at<int>(1, c);
	}
	return total > 0 ? leg / total : 0.0;
}

std::vector<double> CLegClassifier::featureImportance() const
{
	if (!trained()) return {};
	const cv::Mat imp = m_impl->forest->getVarImportance();
	std::vector<double> out;
	double sum = 0;
	for (int k = 0; k < static_cast<int>(imp.total()); ++k) sum += imp.at<float>(k);
	for (int k = 0; k < static_cast<int>(imp.total()); ++k) out.push_back(sum > 0 ? imp.at<float>(k) / sum : 0.0);
	return out;
}

void CLegClassifier::save(const std::string& path) const
{
	if (!trained()) throw std::logic_error("CLegClassifier::save(" + path + "): no model");
	try
	{
		m_impl->forest->save(path);
	}
	catch (const cv::Exception& e)
	{
		throw std::runtime_error(path + ": cannot write leg classifier: " + e.what());
	}
	if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": cannot write leg classifier");
}

CLegClassifier CLegClassifier::load(const std::string& path)
{
	if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": leg classifier model: no such file");
	CLegClassifier c;
	try
	{
		c.m_impl->forest = cv::ml::RTrees::load(path);
	}
	catch (const cv::Exception& e)
	{
		throw std::runtime_error(path + ": not a leg classifier model (" + std::string(e.what()) + ")");
	}
	if (!c.trained())
		throw std::runtime_error(path + ": not a leg classifier model (no trained random forest in it)");
	if (c.m_impl->forest->getVarCount() != static_cast<int>(kLegFeatureCount))
		throw std::runtime_error(path + ": leg classifier model expects " +
								 std::to_string(c.m_impl->forest->getVarCount()) + " features, this build computes " +
								 std::to_string(kLegFeatureCount));
	return c;
}

}  // namespace hslam::dynamic
