/* hslam-bench vision: time per frame of each stage of the camera branch
 * (vision::CFlowAnalyzer's stages called one by one) and of the peer
 * (cv::findEssentialMat + cv::recoverPose on the same tracks), on given
 * pairs (plane warps and simulator frames of a robot moving along an arc). */
#include "bench_common.h"
#include "bench_vision.h"
#include "bench_vision_pairs.h"

#include <opencv2/core/utility.hpp>

namespace hslam::bench
{
namespace
{
constexpr double kMs = 1000.0;

struct TPairTimes
{
	double detect = 0, track = 0, analytic = 0, learned = 0, foe = 0, cues = 0, peer = 0;
};

TPairTimes timePair(const TTruthPair& pair, double yaw_rad, const vision::TMountedCamera& camera,
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

TStageTimes measureStageTimes(const std::string& source, const std::vector<TTruthPair>& pairs,
							  const vision::IRotationFlowModel& learned, int repetitions)
{
	const int width = pairs.front().first.cols, height = pairs.front().first.rows;
	const auto camera = benchCamera(width, height);
	const auto options = benchVisionOptions(width);
	// One OpenCV thread: on the shared 2-core machine its worker threads wait for busy cores.
	const int threads = cv::getNumThreads();
	cv::setNumThreads(1);
	TStageTimes s;
	s.source = source;
	s.width = width;
	s.height = height;
	const double n = static_cast<double>(pairs.size());
	for (const auto& pair : pairs)
	{
		const auto t = timePair(pair, pair.robot_yaw_rad, camera, learned, options, repetitions);
		s.detect_ms += t.detect * kMs / n;
		s.track_ms += t.track * kMs / n;
		s.rotation_analytic_ms += t.analytic * kMs / n;
		s.rotation_learned_ms += t.learned * kMs / n;
		s.foe_ms += t.foe * kMs / n;
		s.cues_ms += t.cues * kMs / n;
		s.peer_ms += t.peer * kMs / n;
	}
	cv::setNumThreads(threads);
	return s;
}

}  // namespace hslam::bench
