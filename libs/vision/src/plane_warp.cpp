#include <hslam/vision/plane_warp.h>

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <stdexcept>

namespace hslam::vision
{
namespace
{
/** Random grey rectangles of several sizes on a mid-grey canvas, blurred. */
cv::Mat proceduralTexture(cv::Size size, cv::RNG& rng)
{
	cv::Mat canvas(size, CV_8UC1, cv::Scalar(128));
	const int count = size.area() / 300;
	for (int i = 0; i < count; ++i)
	{
		const int w = rng.uniform(4, 40), h = rng.uniform(4, 40);
		const cv::Point p(rng.uniform(-w, size.width), rng.uniform(-h, size.height));
		cv::rectangle(canvas, cv::Rect(p.x, p.y, w, h), cv::Scalar(rng.uniform(0, 256)), cv::FILLED);
	}
	cv::GaussianBlur(canvas, canvas, cv::Size(0, 0), 0.8);
	return canvas;
}

void addNoise(cv::Mat& img, double sigma, cv::RNG& rng)
{
	if (sigma <= 0) return;
	cv::Mat noise(img.size(), CV_16SC1);
	rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
	cv::Mat sum;
	img.convertTo(sum, CV_16SC1);
	sum += noise;
	sum.convertTo(img, CV_8UC1);
}
}  // namespace

TPlanePair makePlanePair(const TPlanePairSpec& s)
{
	if (std::abs(s.t[2]) < 1e-9) throw std::invalid_argument("makePlanePair: t_z = 0 puts the FOE at infinity");
	cv::RNG rng(s.seed);
	const int mx = s.size.width / 2, my = s.size.height / 2;  // margin of canvas around the first image
	const cv::Mat canvas = proceduralTexture({s.size.width + 2 * mx, s.size.height + 2 * my}, rng);
	TPlanePair out;
	out.H = s.K * (s.R + s.t * s.n.t() * (1.0 / s.d_m)) * s.K.inv();
	const cv::Matx33d shift(1, 0, -mx, 0, 1, -my, 0, 0, 1);  // canvas -> image 1 pixels
	out.first = canvas(cv::Rect(mx, my, s.size.width, s.size.height)).clone();
	cv::warpPerspective(canvas, out.second, cv::Mat(out.H * shift), s.size, cv::INTER_LINEAR, cv::BORDER_REFLECT);
	addNoise(out.first, s.noise_grey, rng);
	addNoise(out.second, s.noise_grey, rng);
	const cv::Vec3d f = s.K * s.t;
	out.foe = cv::Point2d(f[0] / f[2], f[1] / f[2]);
	return out;
}

TPlanePairSpec planePairForRobotMotion(const TMountedCamera& camera, const mrpt::poses::CPose3D& robotDelta,
									   const cv::Vec3d& n, double d_m, uint64_t seed)
{
	const mrpt::poses::CPose3D M = cameraMotion(camera.sensorPose, robotDelta);
	const auto RM = M.getRotationMatrix();
	TPlanePairSpec s;
	s.K = cameraMatrix(camera.intrinsics);
	s.size = cv::Size(static_cast<int>(camera.intrinsics.ncols), static_cast<int>(camera.intrinsics.nrows));
	for (int r = 0; r < 3; ++r)
		for (int c = 0; c < 3; ++c) s.R(r, c) = RM(c, r);
	const cv::Vec3d tM(M.x(), M.y(), M.z());
	s.t = -(s.R * tM);
	s.n = n;
	s.d_m = d_m;
	s.seed = seed;
	s.robot_yaw_rad = robotDelta.yaw();
	return s;
}

TPlanePairSpec scenarioPair(const TMountedCamera& camera, EPlaneMotion motion, int k, uint64_t seed)
{
	const uint64_t key = seed * 1000003ULL + static_cast<uint64_t>(k) * 7919ULL + static_cast<uint64_t>(motion);
	cv::RNG rng(key);
	const double deg = M_PI / 180.0;
	// The turn direction from a mixed key (splitmix64 finaliser): cv::RNG's first
	// draw from these nearby small seeds always had the same parity, which made
	// every "either way" turn of a scenario the same way (all right turns).
	uint64_t z = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	rng.uniform(0, 2);  // the old draw, kept so the other parameters stay as they were
	const double sign = ((z ^ (z >> 31)) & 1) ? 1.0 : -1.0;
	double dist_m = rng.uniform(0.05, 0.10), dir_rad = 0, yaw_rad = 0;
	switch (motion)
	{
		case EPlaneMotion::translation:
			dir_rad = rng.uniform(-15.0, 15.0) * deg;
			break;
		case EPlaneMotion::translation_rotation:
			yaw_rad = sign * rng.uniform(1.0, 3.0) * deg;
			dir_rad = 0.5 * yaw_rad;  // chord of an arc
			break;
		case EPlaneMotion::rotation:
			dist_m = 0;
			yaw_rad = sign * rng.uniform(0.5, 4.0) * deg;
			break;
	}
	const mrpt::poses::CPose3D delta(dist_m * std::cos(dir_rad), dist_m * std::sin(dir_rad), 0, yaw_rad, 0, 0);
	const double tiltX = rng.uniform(-25.0, 25.0) * deg, tiltY = rng.uniform(-25.0, 25.0) * deg;
	const cv::Vec3d n = cv::normalize(cv::Vec3d(std::sin(tiltY), std::sin(tiltX), 1.0));
	TPlanePairSpec s = planePairForRobotMotion(camera, delta, n, rng.uniform(2.0, 5.0), seed + static_cast<uint64_t>(k));
	if (std::abs(s.t[2]) < 1e-9) s.t[2] = 1e-9;  // pure rotation: no FOE, keep the warp valid
	return s;
}

}  // namespace hslam::vision
