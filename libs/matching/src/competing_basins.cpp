/* hslam: covariance widened over competing ICP basins (competing_basins.h). */
#include <hslam/matching/competing_basins.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/LU>

namespace hslam::matching
{
bool widenForCompetingBasins(TPoseMatch& chosen, const std::vector<TPoseMatch>& results,
							 const TCompetingBasinOptions& options)
{
	if (options.fit_ratio <= 0 || chosen.fit <= 0 || !chosen.covariance.allFinite()) return false;
	const Eigen::Matrix3d information = chosen.covariance.inverse();
	Eigen::Vector3d widest = Eigen::Vector3d::Zero();
	double widestChi2 = 0;
	for (const auto& r : results)
	{
		if (r.quality == EMatchQuality::failed || r.fit < options.fit_ratio * chosen.fit) continue;
		const Eigen::Vector3d d(r.pose.x() - chosen.pose.x(), r.pose.y() - chosen.pose.y(),
								mrpt::math::wrapToPi(r.pose.phi() - chosen.pose.phi()));
		const double chi2 = d.dot(information * d);
		if (chi2 >= options.min_distance_chi2 && chi2 > widestChi2) widestChi2 = chi2, widest = d;
	}
	if (widestChi2 == 0) return false;
	chosen.basin_covariance = chosen.covariance;
	chosen.covariance += widest * widest.transpose();
	return true;
}

}  // namespace hslam::matching
