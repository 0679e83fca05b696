#include <hslam/vision/synthetic_evaluation.h>

#include <algorithm>
#include <cmath>

namespace hslam::vision
{
TFoeErrors foeErrorsOnScenario(const TMountedCamera& camera, EPlaneMotion motion, int pairs, uint64_t seed,
							   const IRotationFlowModel* model, const TVisionOptions& options)
{
	TFoeErrors e;
	const CFlowAnalyzer analyzer(camera, model, options);
	for (int k = 0; k < pairs; ++k)
	{
		const TPlanePairSpec spec = scenarioPair(camera, motion, k, seed);
		const TPlanePair pair = makePlanePair(spec);
		const TFrameAnalysis a = analyzer.analyze(pair.first, pair.second, spec.robot_yaw_rad);
		if (!a.foe.valid)
		{
			++e.invalid;
			continue;
		}
		e.lsq_px.push_back(std::hypot(a.foe.x_px - pair.foe.x, a.foe.y_px - pair.foe.y));
		e.lsq_x_px.push_back(std::abs(a.foe.x_px - pair.foe.x));
		if (a.vote.valid_x) e.vote_x_px.push_back(std::abs(a.vote.x_px - pair.foe.x));
	}
	return e;
}

std::vector<TRotationSample> rotationSamplesOnScenario(const TMountedCamera& camera, int k0, int k1, uint64_t seed,
													   const TFlowOptions& flowOptions, double maxTrackError_px,
													   size_t* dropped)
{
	std::vector<TRotationSample> out;
	for (int k = k0; k < k1; ++k)
	{
		const TPlanePairSpec spec = scenarioPair(camera, EPlaneMotion::rotation, k, seed);
		const TPlanePair pair = makePlanePair(spec);
		for (const auto& f : trackFeatures(pair.first, pair.second, flowOptions).vectors)
		{
			const cv::Vec3d q = pair.H * cv::Vec3d(f.p0.x, f.p0.y, 1.0);
			const double error_px = std::hypot(q[0] / q[2] - f.p1.x, q[1] / q[2] - f.p1.y);
			if (maxTrackError_px > 0 && error_px > maxTrackError_px)
			{
				if (dropped) ++*dropped;
				continue;
			}
			out.push_back({f.p0, f.flow(), spec.robot_yaw_rad});
		}
	}
	return out;
}

double rotationResidualRms(const IRotationFlowModel& model, const std::vector<TRotationSample>& samples)
{
	if (samples.empty()) return NAN;
	double s = 0;
	for (const auto& x : samples)
	{
		const cv::Point2f d = x.flow - model.predict({x.p0}, x.robot_yaw_rad)[0];
		s += d.dot(d);
	}
	return std::sqrt(s / static_cast<double>(samples.size()));
}

cv::Point2d trueFoeOfRobotMotion(const TMountedCamera& camera, const mrpt::poses::CPose3D& robotDelta)
{
	const auto M = cameraMotion(camera.sensorPose, robotDelta);
	const auto R = M.getRotationMatrix();
	const cv::Vec3d t(M.x(), M.y(), M.z());
	cv::Vec3d t2;
	for (int r = 0; r < 3; ++r) t2[r] = R(0, r) * t[0] + R(1, r) * t[1] + R(2, r) * t[2];  // R^T t
	const cv::Vec3d f = cameraMatrix(camera.intrinsics) * t2;
	return {f[0] / f[2], f[1] / f[2]};
}

double medianOf(std::vector<double> v)
{
	if (v.empty()) return NAN;
	std::sort(v.begin(), v.end());
	const size_t n = v.size();
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace hslam::vision
