/* The thesis's 3-5-2 tanh network (figure 176, appendix I.1) with OpenCV's
 * cv::ml::ANN_MLP. Differences from MATLAB's newff: the output neurons are
 * also symmetric sigmoids (OpenCV applies the activation in every layer) with
 * OpenCV's automatic output scaling, and training is RPROP instead of
 * Levenberg-Marquardt. */
#include <hslam/vision/rotation_flow.h>

#include <opencv2/ml.hpp>

#include <cmath>
#include <stdexcept>

namespace hslam::vision
{
struct CLearnedRotationFlow::TImpl
{
	cv::Ptr<cv::ml::ANN_MLP> mlp;
};

CLearnedRotationFlow::CLearnedRotationFlow() : m_impl(std::make_unique<TImpl>()) {}
CLearnedRotationFlow::~CLearnedRotationFlow() = default;
CLearnedRotationFlow::CLearnedRotationFlow(CLearnedRotationFlow&&) noexcept = default;
CLearnedRotationFlow& CLearnedRotationFlow::operator=(CLearnedRotationFlow&&) noexcept = default;

namespace
{
constexpr double kRadToDeg = 180.0 / M_PI;

/** Network inputs of appendix I.1: x/100, y/100 from the image centre, rotation in degrees. */
void fillInputs(cv::Mat& row, const cv::Point2f& p, double yaw_rad, int width, int height)
{
	row.at<float>(0) = static_cast<float>((p.x - 0.5 * width) / 100.0);
	row.at<float>(1) = static_cast<float>((p.y - 0.5 * height) / 100.0);
	row.at<float>(2) = static_cast<float>(yaw_rad * kRadToDeg);
}

double meanFlowX(const std::vector<TRotationSample>& samples, double yaw_rad)
{
	double s = 0;
	int n = 0;
	for (const auto& x : samples)
		if (x.robot_yaw_rad == yaw_rad)
		{
			s += x.flow.x;
			++n;
		}
	return n ? s / n : 0.0;
}
}  // namespace

std::vector<TRotationSample> selectTrainingSamples(const std::vector<TRotationSample>& samples,
												   const TRotationTrainingOptions& o)
{
	std::vector<TRotationSample> out;
	const double maxAngle_rad = o.max_angle_from_horizontal_deg / kRadToDeg;
	for (const auto& s : samples)
	{
		if (s.robot_yaw_rad == 0.0 || o.max_angle_from_horizontal_deg <= 0)
		{
			out.push_back(s);
			continue;
		}
		// Direction of the flow of this rotation: the sign of the mean x flow of its pair(s).
		const double sign = meanFlowX(samples, s.robot_yaw_rad) >= 0 ? 1.0 : -1.0;
		const double angle = std::atan2(std::abs(s.flow.y), std::abs(s.flow.x));
		if (s.flow.x * sign > 0 && angle < maxAngle_rad) out.push_back(s);
	}
	return out;
}

void CLearnedRotationFlow::train(const std::vector<TRotationSample>& samples, int width, int height,
								 const TRotationTrainingOptions& o)
{
	if (samples.size() < 10) throw std::invalid_argument("CLearnedRotationFlow::train: fewer than 10 samples");
	cv::Mat inputs(static_cast<int>(samples.size()), 3, CV_32F), outputs(static_cast<int>(samples.size()), 2, CV_32F);
	for (size_t i = 0; i < samples.size(); ++i)
	{
		cv::Mat row = inputs.row(static_cast<int>(i));
		fillInputs(row, samples[i].p0, samples[i].robot_yaw_rad, width, height);
		outputs.at<float>(static_cast<int>(i), 0) = samples[i].flow.x;
		outputs.at<float>(static_cast<int>(i), 1) = samples[i].flow.y;
	}
	cv::theRNG().state = static_cast<uint64_t>(o.seed) + 1;  // initial weights (OpenCV's per-thread RNG)
	auto mlp = cv::ml::ANN_MLP::create();
	mlp->setLayerSizes(std::vector<int>{3, o.hidden_neurons, 2});
	mlp->setActivationFunction(cv::ml::ANN_MLP::SIGMOID_SYM, 1.0, 1.0);
	mlp->setTrainMethod(cv::ml::ANN_MLP::RPROP);
	mlp->setTermCriteria(cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, o.max_iterations, 1e-7));
	mlp->train(cv::ml::TrainData::create(inputs, cv::ml::ROW_SAMPLE, outputs));
	m_impl->mlp = mlp;
	m_width = width;
	m_height = height;
}

bool CLearnedRotationFlow::trained() const { return m_impl->mlp && m_impl->mlp->isTrained(); }

std::vector<cv::Point2f> CLearnedRotationFlow::predict(const std::vector<cv::Point2f>& p0, double yaw_rad) const
{
	if (!trained()) throw std::logic_error("CLearnedRotationFlow: no model trained or loaded");
	if (p0.empty()) return {};
	cv::Mat inputs(static_cast<int>(p0.size()), 3, CV_32F), outputs;
	for (size_t i = 0; i < p0.size(); ++i)
	{
		cv::Mat row = inputs.row(static_cast<int>(i));
		fillInputs(row, p0[i], yaw_rad, m_width, m_height);
	}
	m_impl->mlp->predict(inputs, outputs);
	std::vector<cv::Point2f> out;
	out.reserve(p0.size());
	for (int i = 0; i < outputs.rows; ++i) out.emplace_back(outputs.at<float>(i, 0), outputs.at<float>(i, 1));
	return out;
}

std::string CLearnedRotationFlow::toYaml() const
{
	if (!trained()) throw std::logic_error("CLearnedRotationFlow::toYaml: no model");
	cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
	fs << "hslam_model" << "rotation_flow_mlp";
	fs << "image_width" << m_width << "image_height" << m_height;
	fs << "mlp" << "{";
	m_impl->mlp->write(fs);
	fs << "}";
	return fs.releaseAndGetString();
}

CLearnedRotationFlow CLearnedRotationFlow::fromYaml(const std::string& yaml)
{
	cv::FileStorage fs(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY);
	if (!fs.isOpened() || static_cast<std::string>(fs["hslam_model"]) != "rotation_flow_mlp")
		throw std::runtime_error("not a rotation-flow model (key hslam_model: rotation_flow_mlp missing)");
	CLearnedRotationFlow model;
	model.m_width = static_cast<int>(fs["image_width"]);
	model.m_height = static_cast<int>(fs["image_height"]);
	if (model.m_width <= 0 || model.m_height <= 0)
		throw std::runtime_error("rotation-flow model: image_width / image_height missing");
	auto mlp = cv::ml::ANN_MLP::create();
	if (fs["mlp"].empty()) throw std::runtime_error("rotation-flow model: node 'mlp' missing");
	mlp->read(fs["mlp"]);
	if (!mlp->isTrained()) throw std::runtime_error("rotation-flow model: node 'mlp' holds no trained network");
	model.m_impl->mlp = mlp;
	return model;
}

}  // namespace hslam::vision
