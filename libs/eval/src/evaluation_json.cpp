/* hslam: writing an evaluation as JSON. */
#include <hslam/common/output_folder.h>
#include <hslam/common/json_text.h>
#include <hslam/eval/evaluation_json.h>

#include <mrpt/core/bits_math.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace hslam::eval
{
namespace
{
/** Ordered key -> JSON value text. */
using TJsonFields = std::vector<std::pair<std::string, std::string>>;

using common::jsonNumber;
using common::jsonString;

std::string jsonCount(size_t value) { return std::to_string(value); }

void addTimeRange(TJsonFields& f, const std::string& prefix, const TTimeRange& t)
{
	f.emplace_back(prefix + "_t_first_s", t.empty ? "null" : jsonNumber(t.first_s, "%.6f"));
	f.emplace_back(prefix + "_t_last_s", t.empty ? "null" : jsonNumber(t.last_s, "%.6f"));
}

void addStats(TJsonFields& f, const std::string& prefix, const std::string& unit, const TErrorStats& s)
{
	f.emplace_back(prefix + "_rmse_" + unit, s.empty() ? "null" : jsonNumber(s.rmse));
	f.emplace_back(prefix + "_mean_" + unit, s.empty() ? "null" : jsonNumber(s.mean));
	f.emplace_back(prefix + "_max_" + unit, s.empty() ? "null" : jsonNumber(s.max));
}

TJsonFields evaluationFields(const TTrajectoryErrors& e)
{
	TJsonFields f = {{"reference", jsonString(e.reference_label)},
					 {"estimate", jsonString(e.estimate_label)},
					 {"max_dt_s", jsonNumber(e.max_dt_s)},
					 {"reference_poses", jsonCount(e.reference_poses)},
					 {"estimate_poses", jsonCount(e.estimate_poses)}};
	addTimeRange(f, "reference", e.reference_time);
	addTimeRange(f, "estimate", e.estimate_time);
	f.emplace_back("matched", jsonCount(e.matched));
	f.emplace_back("unmatched_reference", jsonCount(e.unmatched_reference));
	f.emplace_back("unmatched_estimate", jsonCount(e.unmatched_estimate));
	f.emplace_back("alignment_x_m", jsonNumber(e.ate.alignment.x));
	f.emplace_back("alignment_y_m", jsonNumber(e.ate.alignment.y));
	f.emplace_back("alignment_phi_deg", jsonNumber(mrpt::RAD2DEG(e.ate.alignment.phi)));
	addStats(f, "ate", "m", e.ate.position_m);
	for (const auto& r : e.rpe)
	{
		f.emplace_back("rpe_" + r.name + "_pairs", jsonCount(r.errors.pairs()));
		addStats(f, "rpe_" + r.name + "_trans", "m", r.errors.trans_m);
		addStats(f, "rpe_" + r.name + "_rot", "deg", r.errors.rot_deg);
	}
	return f;
}

void addScanConsistency(TJsonFields& f, const TScanConsistency& c)
{
	f.emplace_back("scan_pairs", jsonCount(c.pairs.size()));
	f.emplace_back("scan_misfit_reference_mean_m", jsonNumber(c.reference_mean_m));
	f.emplace_back("scan_misfit_estimate_mean_m", jsonNumber(c.estimate_mean_m));
	f.emplace_back("scan_pairs_estimate_clearly_worse", jsonCount(c.estimate_worse.size()));
	f.emplace_back("scan_pairs_estimate_clearly_better", jsonCount(c.estimate_better.size()));
}
}  // namespace

std::string evaluationToJson(const TTrajectoryErrors& errors, const TScanConsistency* consistency)
{
	TJsonFields fields = evaluationFields(errors);
	if (consistency) addScanConsistency(fields, *consistency);
	std::string out = "{\n";
	for (size_t k = 0; k < fields.size(); ++k)
		out += "  " + jsonString(fields[k].first) + ": " + fields[k].second + (k + 1 < fields.size() ? ",\n" : "\n");
	return out + "}\n";
}

void writeEvaluationJson(const std::string& path, const TTrajectoryErrors& errors,
						 const TScanConsistency* consistency)
{
	common::writeTextFileAtomically(path, evaluationToJson(errors, consistency));
}

}  // namespace hslam::eval
