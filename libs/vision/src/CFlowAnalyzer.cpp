#include <hslam/vision/CFlowAnalyzer.h>

#include <optional>

namespace hslam::vision
{
namespace
{
/** A scope timer that does nothing without a timer. */
struct TMaybeScope
{
	std::optional<common::CStageTimer::CScope> scope;
	TMaybeScope(common::CStageTimer* timer, const char* stage)
	{
		if (timer) scope.emplace(*timer, stage);
	}
};
}  // namespace

CFlowAnalyzer::CFlowAnalyzer(TMountedCamera camera, const IRotationFlowModel* rotationModel, TVisionOptions options)
	: m_camera(std::move(camera)), m_rotation(rotationModel), m_options(std::move(options))
{
}

TFrameAnalysis CFlowAnalyzer::analyze(const cv::Mat& prevGrey, const cv::Mat& currGrey, double robotYaw_rad,
									  common::CStageTimer* timer) const
{
	TFrameAnalysis a;
	{
		TMaybeScope t(timer, "vision_flow");
		a.flow = trackFeatures(prevGrey, currGrey, m_options.flow);
	}
	{
		TMaybeScope t(timer, "vision_rotation");
		std::vector<cv::Point2f> p0;
		p0.reserve(a.flow.vectors.size());
		for (const auto& f : a.flow.vectors) p0.push_back(f.p0);
		a.predicted = m_rotation ? m_rotation->predict(p0, robotYaw_rad)
								 : std::vector<cv::Point2f>(p0.size(), cv::Point2f(0, 0));
		a.residual = removeRotationFlow(a.flow.vectors, a.predicted);
	}
	{
		TMaybeScope t(timer, "vision_foe");
		a.foe = estimateFoe(a.residual, m_options.foe);
		a.vote = voteFoe(a.residual, prevGrey.cols, prevGrey.rows, m_options.foe);
	}
	{
		TMaybeScope t(timer, "vision_cues");
		a.inconsistent = inconsistentVectors(a.residual, a.foe, m_options.foe);
		a.regions = findMovingRegions(a.residual, a.inconsistent, m_camera, m_options.cues);
	}
	return a;
}

}  // namespace hslam::vision
