/* hslam-bench vision: the peer for ego-motion / FOE, OpenCV's five-point
 * essential matrix (Nister) in RANSAC and its decomposition, on the tracks
 * our Lucas-Kanade stage produced (no odometry: it estimates the rotation
 * itself). */
#include "bench_vision.h"

#include <opencv2/calib3d.hpp>

namespace hslam::bench
{
TEssentialFoe essentialMatrixFoe(const std::vector<vision::TFlowVector>& tracks, const cv::Matx33d& K)
{
	TEssentialFoe out;
	if (tracks.size() < 5) return out;
	std::vector<cv::Point2f> p0, p1;
	for (const auto& f : tracks)
	{
		p0.push_back(f.p0);
		p1.push_back(f.p1);
	}
	cv::Mat mask;
	const cv::Mat E = cv::findEssentialMat(p0, p1, cv::Mat(K), cv::RANSAC, 0.999, 0.3, mask);
	if (E.rows < 3) return out;
	cv::Mat R, t, points;
	// Far points allowed (the overload without it drops points beyond 50 baselines: most of a
	// scene 2-8 m away after 5-10 cm); the cheirality test still picks the decomposition.
	out.inliers = cv::recoverPose(E.rowRange(0, 3), p0, p1, cv::Mat(K), R, t, 1e6, mask, points);
	// X2 = R X1 + t: the second camera heads along t seen from its own frame (up to sign and scale).
	const cv::Vec3d tv(t.at<double>(0), t.at<double>(1), t.at<double>(2));
	if (out.inliers < 5 || std::abs(tv[2]) < 1e-6) return out;
	const cv::Vec3d f = K * tv;
	out.foe = {f[0] / f[2], f[1] / f[2]};
	out.valid = true;
	return out;
}

}  // namespace hslam::bench
