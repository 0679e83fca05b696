/* hslam sim: a pinhole camera for the simulator (implements ICameraModel;
 * thesis 4.8: a forward camera on the P3-DX, off the robot's axis).
 *
 * The 2D world is extruded: walls, furniture and raster cells rise from the
 * floor (z = 0) to wall_height_m, the floor and a ceiling at wall_height_m
 * close it, and every walking person is a cylinder (person_radius_m,
 * person_height_m) around the mean of its two legs. Every image sample casts
 * its ray exactly: the horizontal part through CWorld::castRay (walls) and a
 * world of person cylinders, the vertical part against the wall, floor and
 * ceiling heights. Surfaces carry a procedural texture (grey blocks of two
 * sizes, a brick pattern on walls, tiles on the floor, "clothes" on people)
 * computed from the world coordinates of the hit by a hash (no state), so
 * the same point looks the same from every pose and Shi-Tomasi corners exist
 * everywhere. Each pixel averages supersampling^2 rays in an N-rooks pattern
 * (every ray in its own sample column and row, so a texture edge moving
 * across the pixel changes its value in supersampling^2 steps: the area
 * integration of a real sensor pixel, which sub-pixel tracking relies on),
 * then Gaussian noise. Intrinsics are the thesis camera's by default
 * (vision::TCameraIntrinsicsOptions); the image is grey (8 bit) or RGB. */
#pragma once

#include <hslam/sim/ICameraModel.h>
#include <hslam/vision/camera_geometry.h>
#include <mrpt/math/TPoint3D.h>

#include <optional>
#include <string>

namespace hslam::sim
{
struct TCameraSimOptions  //!< [camera] of a simulator INI
{
	bool enabled = false;
	double rate_hz = 5;
	std::string label = "CAMERA";
	bool grey = true;  //!< false: RGB (tinted surfaces)
	vision::TCameraIntrinsicsOptions intrinsics;
	vision::TCameraMountOptions mount;
	double wall_height_m = 2.5;
	double person_radius_m = 0.2;
	double person_height_m = 1.75;
	double max_range_m = 60;
	int supersampling = 4;  //!< rays per pixel side (ss^2 rays per pixel, N-rooks pattern)
	double noise_grey = 1.0;  //!< sigma of the additive pixel noise (grey levels)
	int jpeg_quality = 0;  //!< >0: the writer stores RGB images JPEG-compressed at this quality (MRPT CImage)

	template <class V>
	void visit(V& v)
	{
		v.flag("enabled", enabled);
		v.real("rate_hz", rate_hz, 0.1, 100.0);
		v.text("label", label);
		v.flag("grey", grey);
		intrinsics.visit(v);
		mount.visit(v);
		v.real("wall_height_m", wall_height_m, 0.2, 20.0);
		v.real("person_radius_m", person_radius_m, 0.05, 1.0);
		v.real("person_height_m", person_height_m, 0.2, 3.0);
		v.real("max_range_m", max_range_m, 1.0, 1000.0);
		v.integer("supersampling", supersampling, 1, 8);
		v.real("noise_grey", noise_grey, 0.0, 50.0);
		v.integer("jpeg_quality", jpeg_quality, 0, 100);
	}
};

class CPinholeCameraSimulator : public ICameraModel
{
   public:
	explicit CPinholeCameraSimulator(TCameraSimOptions options);

	double rate_hz() const override { return m_options.rate_hz; }
	/** A CObservationImage (cameraParams, cameraPose = the mounting) seen from robotTruePose. */
	mrpt::obs::CObservation::Ptr render(const CWorld& world, const mrpt::math::TPose2D& robotTruePose,
										std::mt19937_64& rng) const override;

	/** The surface point seen through image point (u_px, v_px) (pixel centres
	 * at whole numbers, as OpenCV) from robotTruePose, in the camera frame (z =
	 * depth); nullopt where the ray meets nothing. One exact ray, no texture:
	 * the ground truth of the flow of a tracked corner. */
	std::optional<mrpt::math::TPoint3D> surfacePoint(const CWorld& world, const mrpt::math::TPose2D& robotTruePose,
													 double u_px, double v_px) const;

	const vision::TMountedCamera& camera() const { return m_camera; }
	const TCameraSimOptions& options() const { return m_options; }

   private:
	TCameraSimOptions m_options;
	vision::TMountedCamera m_camera;
};

}  // namespace hslam::sim
