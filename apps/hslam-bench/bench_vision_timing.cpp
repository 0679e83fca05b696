/* hslam-bench vision: time per frame of each stage of the camera branch
 * (vision::CFlowAnalyzer's stages called one by one) and of the peer
 * (cv::findEssentialMat + cv::recoverPose on the same tracks), on plane-warp
 * pairs of a robot moving along an arc. */
#include "bench_common.h"
#include "bench_vision.h"

namespace hslam::bench
{
namespace
{
constexpr double kMs = 1000.0;

struct TPairTimes
{
	double detect = 0, track = 0, analytic = 0, learned = 0, foe = 0, cues = 0, peer = 0;
};

TPairTimes timePair(const vision::TPlanePair& pair, double yaw_rad, const vision::TMountedCamera& camera,
					const vision::IRotationFlowModel& learned, const vision::TVisionOptions& o, int reps)
{
	TPairTimes t;
	std::vector<cv::Point2f> corners;
	t.detect = bestTimeOf(reps, [&] { corners = vision::detectCorners(pair.first, o.flow); });
	vision::TFlowResult flow;
	t.track = bestTimeOf(reps, [&] { flow = vision::trackCorners(pair.first, pair.second, corners, o.flow); });
	std::vector<cv::Point2f> p0;
	for (const auto& f : flow.vectors) p0.push_back(f.p0);
	const vision::CAnalyticRotationFlow analytic(camera);
	std::vector<vision::TFlowVector> residual;
	const auto removal = [&](const vision::IRotationFlowModel& m)
	{ return bestTimeOf(reps, [&] { residual = vision::removeRotationFlow(flow.vectors, m.predict(p0, yaw_rad)); }); };
	t.learned = removal(learned);
	t.analytic = removal(analytic);  // last: its residual goes on
	vision::TFoeEstimate foe;
	t.foe = bestTimeOf(reps, [&] {
		foe = vision::estimateFoe(residual, o.foe);
		vision::voteFoe(residual, pair.first.cols, pair.first.rows, o.foe);
	});
	t.cues = bestTimeOf(reps, [&] {
		vision::findMovingRegions(residual, vision::inconsistentVectors(residual, foe, o.foe), camera, o.cues);
	});
	const cv::Matx33d K = vision::cameraMatrix(camera.intrinsics);
	t.peer = bestTimeOf(reps, [&] { essentialMatrixFoe(flow.vectors, K); });
	return t;
}
}  // namespace

TStageTimes measureStageTimes(int width, int height, const vision::IRotationFlowModel& learned, int pairs,
							  int repetitions)
{
	const auto camera = benchCamera(width, height);
	const auto options = benchVisionOptions(width);
	TStageTimes s;
	s.width = width;
	s.height = height;
	for (int k = 0; k < pairs; ++k)
	{
		const auto spec = vision::scenarioPair(camera, vision::EPlaneMotion::translation_rotation, k, 77);
		const auto t = timePair(vision::makePlanePair(spec), spec.robot_yaw_rad, camera, learned, options, repetitions);
		s.detect_ms += t.detect * kMs / pairs;
		s.track_ms += t.track * kMs / pairs;
		s.rotation_analytic_ms += t.analytic * kMs / pairs;
		s.rotation_learned_ms += t.learned * kMs / pairs;
		s.foe_ms += t.foe * kMs / pairs;
		s.cues_ms += t.cues * kMs / pairs;
		s.peer_ms += t.peer * kMs / pairs;
	}
	return s;
}

}  // namespace hslam::bench
