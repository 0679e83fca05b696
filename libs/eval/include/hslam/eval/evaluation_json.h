/* hslam: an evaluation as a flat JSON object, for scripts and result tables.
 *
 * Keys (units in the names): reference, estimate, max_dt_s, reference_poses,
 * estimate_poses, reference_t_first_s, reference_t_last_s,
 * estimate_t_first_s, estimate_t_last_s, matched, unmatched_reference,
 * unmatched_estimate, alignment_x_m, alignment_y_m, alignment_phi_deg,
 * ate_rmse_m, ate_mean_m, ate_max_m, and per RPE family NAME
 * ("consecutive", "1m", "5m"): rpe_NAME_pairs, rpe_NAME_trans_{rmse,mean,max}_m,
 * rpe_NAME_rot_{rmse,mean,max}_deg. Statistics of a family without pairs
 * are null. With a scan consistency (scan_consistency.h) also: scan_pairs,
 * scan_misfit_reference_mean_m, scan_misfit_estimate_mean_m,
 * scan_pairs_estimate_clearly_worse, scan_pairs_estimate_clearly_better. */
#pragma once

#include <hslam/eval/evaluate_trajectory.h>
#include <hslam/eval/scan_consistency.h>

#include <string>

namespace hslam::eval
{
/** The JSON text (one key per line). */
std::string evaluationToJson(const TTrajectoryErrors& errors, const TScanConsistency* consistency = nullptr);

/** Writes evaluationToJson() to a file; throws std::runtime_error naming the
 * file if it cannot be written. */
void writeEvaluationJson(const std::string& path, const TTrajectoryErrors& errors,
						 const TScanConsistency* consistency = nullptr);

}  // namespace hslam::eval
