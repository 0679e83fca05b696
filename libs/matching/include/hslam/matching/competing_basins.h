/* hslam: a scan-match result's covariance widened when another seed's result
 * fits the reference nearly as well (issue 12, "Recovery").
 *
 * ICP's covariance (icp_covariance.h) describes the basin ICP converged in,
 * not the chance that it converged in the wrong one. When the front-end's
 * seeds (line result, UKF prediction, refused-match seed) end in two basins
 * whose fits (alignment_fit.h) are close, the scan does not decide between
 * them and the posterior is bimodal. csail, started at entry 70, t = 55 s:
 * turning in place at 40 deg/s with scans 1 s apart, the seeds ended 42 deg
 * apart with fits 0.403 and 0.330; the better-fitting result was the wrong
 * one, accepted at NIS 13 with a 1.6 deg standard deviation, and the run
 * ended at ATE 2.2 m. The second moment of the two modes about the chosen
 * one (d d^T, d the difference of the results) is added to the covariance,
 * so the filter weighs the match against the prediction by how far apart
 * the candidates are, rather than trusting a coin toss to 1.6 deg. */
#pragma once

#include <hslam/matching/match_result.h>

#include <vector>

namespace hslam::matching
{
struct TCompetingBasinOptions
{
	/** A result fitting at least this fraction of the chosen one's fit
	 * competes with it; 0 = off. Range [0, 1]. */
	double fit_ratio = 0.75;
	/** ...when it lies outside the chosen result's covariance ellipse by
	 * this squared Mahalanobis distance (3-dof chi^2 99.9 %: 16.27). */
	double min_distance_chi2 = 16.27;
};

/** Whether `other` lies in another basin than `chosen` (outside its
 * covariance by min_distance_chi2) and fits at least fit_ratio as well. */
bool competesWith(const TPoseMatch& chosen, const TPoseMatch& other, const TCompetingBasinOptions& options);

/** Adds d d^T to chosen.covariance for the farthest competing result of
 * `results` (which may contain `chosen` itself), keeping the basin's own
 * covariance in chosen.basin_covariance; returns whether any competed. */
bool widenForCompetingBasins(TPoseMatch& chosen, const std::vector<TPoseMatch>& results,
							 const TCompetingBasinOptions& options);

}  // namespace hslam::matching
