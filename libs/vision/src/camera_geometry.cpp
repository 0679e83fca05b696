#include <hslam/vision/camera_geometry.h>

#include <cmath>

namespace hslam::vision
{
mrpt::img::TCamera cameraFromOptions(const TCameraIntrinsicsOptions& o)
{
	mrpt::img::TCamera cam;
	cam.ncols = static_cast<uint32_t>(o.width_px);
	cam.nrows = static_cast<uint32_t>(o.height_px);
	// The pixel pitch is that of the 640-pixel sensor; a 320-pixel image bins 2 x 2.
	const double f_px = o.focal_length_mm / o.pixel_size_mm * (o.width_px / 640.0);
	cam.setIntrinsicParamsFromValues(f_px, f_px, 0.5 * o.width_px, 0.5 * o.height_px);
	cam.dist.fill(0.0);
	return cam;
}

cv::Matx33d cameraMatrix(const mrpt::img::TCamera& c)
{
	return cv::Matx33d(c.fx(), 0.0, c.cx(), 0.0, c.fy(), c.cy(), 0.0, 0.0, 1.0);
}

mrpt::poses::CPose3D forwardCameraPose(double x_m, double y_m, double z_m, double yaw_rad, double pitch_rad)
{
	// Camera z (optical axis) along robot x, camera x along robot -y, camera y along robot -z;
	// then the pan (about robot z) and the tilt (about the camera's x axis, positive down).
	const mrpt::poses::CPose3D pan(x_m, y_m, z_m, yaw_rad, 0.0, 0.0);
	const mrpt::poses::CPose3D axes(0, 0, 0, -M_PI / 2, 0.0, -M_PI / 2);
	const mrpt::poses::CPose3D tilt(0, 0, 0, 0.0, 0.0, -pitch_rad);
	return pan + axes + tilt;
}

TMountedCamera mountedCamera(const TCameraIntrinsicsOptions& intrinsics, const TCameraMountOptions& m)
{
	return {cameraFromOptions(intrinsics), forwardCameraPose(m.x_m, m.y_m, m.z_m, m.yaw_rad, m.pitch_rad)};
}

mrpt::poses::CPose3D cameraMotion(const mrpt::poses::CPose3D& sensorPose, const mrpt::poses::CPose3D& robotDelta)
{
	return (-sensorPose) + robotDelta + sensorPose;
}

double robotBearingOfPixel(const TMountedCamera& camera, double u_px, double v_px)
{
	const auto& c = camera.intrinsics;
	const double xc = (u_px - c.cx()) / c.fx(), yc = (v_px - c.cy()) / c.fy();
	const auto R = camera.sensorPose.getRotationMatrix();
	const double rx = R(0, 0) * xc + R(0, 1) * yc + R(0, 2);
	const double ry = R(1, 0) * xc + R(1, 1) * yc + R(1, 2);
	return std::atan2(ry, rx);
}

}  // namespace hslam::vision
