#include <hslam/common/options_io.h>
#include <hslam/slam/CVisionStage.h>
#include <hslam/vision/vision_drawing.h>
#include <mrpt/math/wrap2pi.h>
#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <sstream>

namespace hslam::slam
{
namespace
{
vision::CLearnedRotationFlow loadModel(const std::string& path)
{
	std::ifstream f(path);
	if (!f) throw common::config_error("[vision] rotation_model_file: cannot open '" + path + "'");
	std::stringstream text;
	text << f.rdbuf();
	try
	{
		return vision::CLearnedRotationFlow::fromYaml(text.str());
	}
	catch (const std::exception& e)
	{
		throw common::config_error("[vision] rotation_model_file: '" + path + "': " + e.what());
	}
}
}  // namespace

std::vector<dynamic::TCameraCue> cameraCues(const TVisionRow& row)
{
	std::vector<dynamic::TCameraCue> cues;
	for (const auto& r : row.regions) cues.push_back({row.t_s, r.bearing_min_rad, r.bearing_max_rad});
	return cues;
}

CVisionStage::CVisionStage(const mrpt::config::CConfigFileBase& cfg)
	: m_options(common::loadedOptions<TVisionStageOptions>(cfg, "vision"))
{
	if (m_options.analysis.enabled && m_options.analysis.rotation_model == "learned")
	{
		if (m_options.analysis.rotation_model_file.empty())
			throw common::config_error("[vision] rotation_model_file: needed with rotation_model = learned");
		m_learned = std::make_unique<vision::CLearnedRotationFlow>(loadModel(m_options.analysis.rotation_model_file));
	}
}

CVisionStage::~CVisionStage() = default;

const vision::IRotationFlowModel* CVisionStage::rotationModelFor(const vision::TMountedCamera& camera)
{
	const std::string& kind = m_options.analysis.rotation_model;
	if (kind == "learned") return m_learned.get();
	if (kind == "none") return nullptr;
	m_analytic = std::make_unique<vision::CAnalyticRotationFlow>(camera);  // cheap; the camera may change
	return m_analytic.get();
}

void CVisionStage::process(const mrpt::obs::CObservationImage& obs,
						   const std::optional<mrpt::poses::CPose2D>& odometryPose, common::CStageTimer& timer)
{
	if (!m_options.analysis.enabled || (!m_options.camera_label.empty() && obs.sensorLabel != m_options.camera_label))
	{
		++m_ignored;
		return;
	}
	cv::Mat grey;
	{
		common::CStageTimer::CScope t(timer, "vision_image");
		grey = vision::greyImageOf(obs);
	}
	const size_t index = m_images++;
	const bool paired = !m_previous.empty() && m_previous.size() == grey.size();
	const bool rotationKnown = odometryPose && m_previousPose;
	const double yaw_rad = rotationKnown ? mrpt::math::wrapToPi(odometryPose->phi() - m_previousPose->phi()) : 0.0;
	if (paired)
	{
		if (m_learned && (m_learned->imageWidth() != grey.cols || m_learned->imageHeight() != grey.rows))
			throw std::runtime_error("[vision] rotation_model_file: the model was trained for other image sizes");
		const auto camera = vision::mountedCameraOf(obs, vision::cameraFromOptions(m_options.fallback_intrinsics));
		const auto* model = rotationKnown ? rotationModelFor(camera) : nullptr;
		const vision::CFlowAnalyzer analyzer(camera, model, m_options.analysis);
		vision::TFrameAnalysis a = analyzer.analyze(m_previous, grey, yaw_rad, &timer);
		TVisionRow row{index, mrpt::Clock::toDouble(obs.timestamp), yaw_rad * 180.0 / M_PI, rotationKnown,
					   a.flow.corners, a.flow.vectors.size(), a.flow.lost, a.flow.fb_rejected, a.foe, a.vote,
					   a.regions, a.inconsistent.size()};
		row.foe.inlier.clear();
		m_rows.push_back(std::move(row));
		const int every = m_options.debug_every_frames;
		if (every > 0 && index % static_cast<size_t>(every) == 0 &&
			m_debug.size() < static_cast<size_t>(m_options.debug_max_images))
		{
			std::vector<uint8_t> png;
			cv::imencode(".png", vision::drawAnalysisPanels(grey, a), png);
			m_debug.emplace_back(index, std::move(png));
		}
	}
	m_previous = grey;
	m_previousPose = odometryPose;
}

}  // namespace hslam::slam
