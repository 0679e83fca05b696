/* hslam: the result every scan matcher returns (thesis 4.4.2 iii output:
 * pose change, plus what the UKF needs: a covariance and a quality flag). */
#pragma once

#include <mrpt/poses/CPose2D.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>

namespace hslam::matching
{
enum class EMatchQuality
{
	good,  //!< trust with its covariance
	weak,  //!< usable but doubtful (thesis: best line weight < 0.9; ICP goodness low)
	failed  //!< no estimate; do not use
};

const char* toString(EMatchQuality quality);

struct TPoseMatch
{
	/** Frame-to-frame matchers: pose of the current scan in the previous
	 * scan's robot frame. Scan-to-map matchers: pose in the map frame. */
	mrpt::poses::CPose2D pose;
	Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  //!< of (x m, y m, theta rad)
	EMatchQuality quality = EMatchQuality::failed;
	double score = 0;  //!< matcher-specific: best line weight (lines), goodness (ICP)
	size_t correspondences = 0;  //!< paired lines or matched points
	/** ICP: mean Gaussian likelihood of the points at `pose` (alignment_fit.h),
	 * which decides between the results of several seeds; 0 when not computed. */
	double fit = 0;
	/** Set when `covariance` was widened over competing basins
	 * (competing_basins.h): the covariance of the chosen basin alone. */
	std::optional<Eigen::Matrix3d> basin_covariance;
	/** ICP: alignments run for this result (the first seed and its restarts). */
	size_t seeds_aligned = 0;
	std::string method;  //!< what produced it, e.g. "lines", "lines:points", "icp"
};

}  // namespace hslam::matching
