#include <hslam/vision/rotation_flow.h>

#include <stdexcept>

namespace hslam::vision
{
cv::Matx33d CAnalyticRotationFlow::homography(double robotYaw_rad) const
{
	const mrpt::poses::CPose3D robotTurn(0, 0, 0, robotYaw_rad, 0, 0);
	const auto R = cameraMotion(m_camera.sensorPose, robotTurn).getRotationMatrix();
	cv::Matx33d Rt;  // camera 2 seen from camera 1 is R: a point at infinity moves by R^T
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) Rt(r, c) = R(c, r);
	const cv::Matx33d K = cameraMatrix(m_camera.intrinsics);
	return K * Rt * K.inv();
}

std::vector<cv::Point2f> CAnalyticRotationFlow::predict(const std::vector<cv::Point2f>& p0,
														double robotYaw_rad) const
{
	const cv::Matx33d H = homography(robotYaw_rad);
	std::vector<cv::Point2f> out;
	out.reserve(p0.size());
	for (const auto& p : p0)
	{
		const cv::Vec3d q = H * cv::Vec3d(p.x, p.y, 1.0);
		out.emplace_back(static_cast<float>(q[0] / q[2] - p.x), static_cast<float>(q[1] / q[2] - p.y));
	}
	return out;
}

std::vector<TFlowVector> removeRotationFlow(const std::vector<TFlowVector>& flow,
											const std::vector<cv::Point2f>& predicted)
{
	if (flow.size() != predicted.size())
		throw std::invalid_argument("removeRotationFlow: one prediction per flow vector is needed");
	std::vector<TFlowVector> out;
	out.reserve(flow.size());
	for (size_t i = 0; i < flow.size(); ++i) out.push_back({flow[i].p0 + predicted[i], flow[i].p1});
	return out;
}

}  // namespace hslam::vision
