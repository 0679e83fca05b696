/* hslam vision: the pinhole camera of thesis 4.8.2 i and its mounting on the
 * robot.
 *
 * The thesis camera is a Point Grey BFLY-U3-03S2C-CS (1/3" sensor, 4.8 x 3.6
 * mm, 640 x 480 pixels of 0.0075 mm) with a 6 mm DF6HA-1B lens, so
 * f = 6 / 0.0075 = 800 px at 640 x 480 (400 px at 320 x 240). The camera
 * frame follows MRPT/OpenCV: z forward along the optical axis, x right, y
 * down; `sensorPose` is the camera frame in the robot frame (what
 * mrpt::obs::CObservationImage::cameraPose holds), e.g. a forward camera is
 * CPose3D(x, y, z, -90 deg, 0, -90 deg). */
#pragma once

#include <mrpt/img/TCamera.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

namespace hslam::vision
{
struct TCameraIntrinsicsOptions  //!< thesis camera by default (4.8.2 i)
{
	double focal_length_mm = 6.0;  //!< DF6HA-1B lens
	double pixel_size_mm = 0.0075;  //!< at 640 x 480; scaled for other resolutions
	int width_px = 640;
	int height_px = 480;

	template <class V>
	void visit(V& v)
	{
		v.real("focal_length_mm", focal_length_mm, 0.5, 100.0);
		v.real("pixel_size_mm", pixel_size_mm, 0.0005, 0.1);
		v.integer("width_px", width_px, 16, 8192);
		v.integer("height_px", height_px, 16, 8192);
	}
};

struct TCameraMountOptions  //!< where the camera sits on the robot
{
	// Off the robot's axis like the thesis's camera on its pan-tilt unit (figure 168; exact values unknown).
	double x_m = 0.15, y_m = -0.05, z_m = 0.45;
	double yaw_rad = 0;  //!< optical axis relative to the robot's x axis
	double pitch_rad = 0;  //!< positive looks down

	template <class V>
	void visit(V& v)
	{
		v.real("camera_x_m", x_m, -5.0, 5.0);
		v.real("camera_y_m", y_m, -5.0, 5.0);
		v.real("camera_z_m", z_m, 0.01, 5.0);
		v.degrees("camera_yaw_deg", yaw_rad, -180.0, 180.0);
		v.degrees("camera_pitch_deg", pitch_rad, -60.0, 60.0);
	}
};

/** MRPT camera parameters for the options (principal point at the image
 * centre; the pixel size is that of a 640-pixel-wide sensor scaled to width_px). */
mrpt::img::TCamera cameraFromOptions(const TCameraIntrinsicsOptions& options);

/** Camera matrix K of MRPT camera parameters. */
cv::Matx33d cameraMatrix(const mrpt::img::TCamera& camera);

/** A camera mounted on the robot: intrinsics and the camera pose in the robot frame. */
struct TMountedCamera
{
	mrpt::img::TCamera intrinsics;
	mrpt::poses::CPose3D sensorPose;  //!< camera frame (z forward, x right, y down) in the robot frame
};

/** The camera pose (in robot frame) of a camera looking along the robot's x
 * axis turned left by yaw_rad and down by pitch_rad, at (x, y, z) in the robot frame. */
mrpt::poses::CPose3D forwardCameraPose(double x_m, double y_m, double z_m, double yaw_rad = 0.0,
									   double pitch_rad = 0.0);
/** The mounted camera of the options. */
TMountedCamera mountedCamera(const TCameraIntrinsicsOptions& intrinsics, const TCameraMountOptions& mount);

/** Pose of the camera at the second frame in the camera frame of the first,
 * when the robot moves by `robotDelta` (robot 2 in robot 1): (-S) + D + S. */
mrpt::poses::CPose3D cameraMotion(const mrpt::poses::CPose3D& sensorPose, const mrpt::poses::CPose3D& robotDelta);

/** Bearing (rad, CCW from the robot's x axis, in the robot's xy plane) of
 * the viewing ray through image point (u, v). */
double robotBearingOfPixel(const TMountedCamera& camera, double u_px, double v_px);

}  // namespace hslam::vision
