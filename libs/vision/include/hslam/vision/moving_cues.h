/* hslam vision: moving-object cues (beyond the thesis, which shows in figure
 * 167 b and 181 that flow inconsistent with the ego-motion marks a moving
 * object or a bad track, but does not use it).
 *
 * A residual vector longer than the noise threshold that is not an inlier of
 * the FOE (its line misses the FOE, or it points the wrong way along it) is
 * inconsistent with a static world seen from the moving camera. With no FOE
 * or one of confidence below kMinFoeConfidence (robot at rest or turning on
 * the spot, too few vectors) only vectors kNoFoeLengthFactor times longer
 * than the noise threshold are. Inconsistent
 * vectors are grouped with cv::partition (within cluster_distance_px of each
 * other) into image regions; a region with at least min_vectors vectors is
 * a cue, with the bearing of its centre in the robot frame so it can be
 * compared with laser leg tracks. */
#pragma once

#include <hslam/vision/camera_geometry.h>
#include <hslam/vision/foe.h>

#include <vector>

namespace hslam::vision
{
struct TMovingCueOptions  //!< [vision] keys of the cue clustering
{
	double cluster_distance_px = 40;  //!< at 640 x 480
	int min_vectors = 3;

	template <class V>
	void visit(V& v)
	{
		v.real("cue_cluster_distance_px", cluster_distance_px, 1.0, 1000.0);
		v.integer("cue_min_vectors", min_vectors, 1, 1000);
	}
};

struct TMovingRegion
{
	cv::Rect2f box;  //!< bounding box of the vectors' second points (px)
	cv::Point2f centre;  //!< mean of the second points (px)
	size_t vectors = 0;
	double mean_residual_px = 0;  //!< mean residual length
	double bearing_rad = 0;  //!< of the centre, robot frame (CCW from x)
	double bearing_min_rad = 0, bearing_max_rad = 0;  //!< of the box's left and right edges (min <= max)
};

/** An FOE with less confidence does not decide consistency. */
constexpr double kMinFoeConfidence = 0.1;
/** Without an FOE a vector must be this many times the noise threshold long. */
constexpr double kNoFoeLengthFactor = 3.0;

/** Indices of the residual vectors inconsistent with `foe`. */
std::vector<size_t> inconsistentVectors(const std::vector<TFlowVector>& residual, const TFoeEstimate& foe,
										const TFoeOptions& foeOptions);

/** Regions of inconsistent vectors, largest first. */
std::vector<TMovingRegion> findMovingRegions(const std::vector<TFlowVector>& residual,
											 const std::vector<size_t>& inconsistent, const TMountedCamera& camera,
											 const TMovingCueOptions& options);

}  // namespace hslam::vision
