/* hslam: covariance widened over competing ICP basins (competing_basins.h). */
#include <hslam/matching/competing_basins.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/LU>

namespace hslam::matching
{
namespace
{
Eigen::Vector3d difference(const TPoseMatch& a, const TPoseMatch& b)
{
	return {a.pose.x() - b.pose.x(), a.pose.y() - b.pose.y(), mrpt::math::wrapToPi(a.pose.phi() - b.pose.phi())};
}

/** Squared Mahalanobis distance of `other` from `chosen` when it competes, else 0. */
double competingChi2(const TPoseMatch& chosen, const TPoseMatch& other, const TCompetingBasinOptions& options)
{
	if (options.fit_ratio <= 0 || chosen.fit <= 0 || !chosen.covariance.allFinite()) return 0;
	if (other.quality == EMatchQuality::failed || other.fit < options.fit_ratio * chosen.fit) return 0;
	const Eigen::Vector3d d = difference(other, chosen);
	const double chi2 = d.dot(chosen.covariance.inverse() * d);
	return chi2 >= options.min_distance_chi2 ? chi2 : 0;
}
}  // namespace

bool competesWith(const TPoseMatch& chosen, const TPoseMatch& other, const TCompetingBasinOptions& options)
{
	return competingChi2(chosen, other, options) > 0;
}

bool widenForCompetingBasins(TPoseMatch& chosen, const std::vector<TPoseMatch>& results,
							 const TCompetingBasinOptions& options)
{
	Eigen::Vector3d widest = Eigen::Vector3d::Zero();
	double widestChi2 = 0;
	for (const auto& r : results)
		if (const double chi2 = competingChi2(chosen, r, options); chi2 > widestChi2)
			widestChi2 = chi2, widest = difference(r, chosen);
	if (widestChi2 == 0) return false;
	chosen.basin_covariance = chosen.covariance;
	chosen.covariance += widest * widest.transpose();
	return true;
}

}  // namespace hslam::matching
