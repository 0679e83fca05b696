/* hslam: the evaluation pipeline: associate, ATE, RPE. */
#include <hslam/eval/evaluate_trajectory.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace hslam::eval
{
namespace
{
std::string describeTrajectory(const std::string& label, size_t numPoses, const TTimeRange& range)
{
	if (range.empty) return "'" + label + "' has no poses";
	char text[160];
	std::snprintf(text, sizeof(text), " has %zu poses at t = [%.3f, %.3f] s", numPoses, range.first_s,
				  range.last_s);
	return "'" + label + "'" + text;
}

[[noreturn]] void throwTooFewMatches(const TTrajectoryErrors& e)
{
	char head[160];
	std::snprintf(head, sizeof(head), "only %zu pose(s) matched within %g s (at least 3 needed: 2 poses always align exactly): reference ",
				  e.matched, e.max_dt_s);
	throw std::runtime_error(
		head + describeTrajectory(e.reference_label, e.reference_poses, e.reference_time) + ", estimate " +
		describeTrajectory(e.estimate_label, e.estimate_poses, e.estimate_time) +
		" (are both timestamped with the same clock?)");
}

std::vector<TRpeResult> computeAllRpe(const TAssociation& matches, const std::vector<double>& distances_m)
{
	std::vector<TRpeResult> out;
	out.push_back({"consecutive", 0.0,
				   computeRelativePoseError(matches.reference, matches.estimate, consecutivePairs(matches.size()))});
	for (const double d_m : distances_m)
	{
		const auto pairs = pairsByTravelledDistance(matches.reference, d_m);
		out.push_back({rpeDistanceName(d_m), d_m,
					   computeRelativePoseError(matches.reference, matches.estimate, pairs)});
	}
	return out;
}

/** Coordinates beyond 1e9 m (or not finite) would overflow the squared
 * errors into inf: refused, naming the file and the pose (issue 15 item 6). */
void checkCoordinates(const common::TTrajectory2D& poses, const std::string& label)
{
	constexpr double LIMIT_M = 1e9;
	for (size_t i = 0; i < poses.size(); ++i)
	{
		const auto& p = poses[i];
		if (!std::isfinite(p.t_s) || !std::isfinite(p.pose.phi) || !(std::abs(p.pose.x) <= LIMIT_M) ||
			!(std::abs(p.pose.y) <= LIMIT_M))
			throw std::runtime_error("'" + label + "': pose " + std::to_string(i + 1) +
									 ": coordinates must be finite and within 1e9 m");
	}
}

/** Rejects bad options before any work, whatever the data. */
void checkOptions(const TEvaluationOptions& options)
{
	if (!(options.max_dt_s >= 0) || !std::isfinite(options.max_dt_s))
		throw std::invalid_argument("max_dt must be a finite number >= 0 s, got " + std::to_string(options.max_dt_s));
	for (const double d_m : options.rpe_distances_m)
		if (!(d_m > 0) || !std::isfinite(d_m))
			throw std::invalid_argument("RPE distances must be finite and > 0 m, got " + std::to_string(d_m));
}

}  // namespace

std::string rpeDistanceName(double distance_m)
{
	char text[64];
	std::snprintf(text, sizeof(text), "%gm", distance_m);
	return text;
}

TTrajectoryErrors evaluateTrajectory(const common::TTrajectory2D& reference,
									 const common::TTrajectory2D& estimate, const TEvaluationOptions& options)
{
	checkOptions(options);
	TTrajectoryErrors e;
	e.reference_label = options.reference_label;
	e.estimate_label = options.estimate_label;
	e.max_dt_s = options.max_dt_s;
	e.reference_poses = reference.size();
	e.estimate_poses = estimate.size();
	checkCoordinates(reference, options.reference_label);
	checkCoordinates(estimate, options.estimate_label);
	e.reference_time = timeRange(reference);
	e.estimate_time = timeRange(estimate);

	const TAssociation matches = associateByTimestamp(reference, estimate, options.max_dt_s);
	e.matched = matches.size();
	e.unmatched_reference = matches.unmatched_reference;
	e.unmatched_estimate = matches.unmatched_estimate;
	if (e.matched < 3) throwTooFewMatches(e);

	e.ate = computeAbsoluteTrajectoryError(matches.reference, matches.estimate);
	e.rpe = computeAllRpe(matches, options.rpe_distances_m);
	return e;
}

TTrajectoryErrors evaluateTumFiles(const std::string& referencePath, const std::string& estimatePath,
								   TEvaluationOptions options)
{
	options.reference_label = referencePath;
	options.estimate_label = estimatePath;
	const common::TTrajectory2D reference = common::readTumFile(referencePath);  // read first: its
	const common::TTrajectory2D estimate = common::readTumFile(estimatePath);  // errors come first
	return evaluateTrajectory(reference, estimate, options);
}

}  // namespace hslam::eval
