/* hslam: scan-to-scan misfit of trajectories (scan_consistency.h). */
#include <hslam/common/range_data.h>
#include <hslam/eval/scan_consistency.h>
#include <hslam/io/rawlog_scans.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>

namespace hslam::eval
{
namespace
{
/** The pose nearest in time to t_s within max_dt_s, from a trajectory sorted by time. */
std::optional<mrpt::poses::CPose2D> poseAt(const common::TTrajectory2D& sorted, double t_s, double max_dt_s)
{
	const auto later = std::lower_bound(sorted.begin(), sorted.end(), t_s,
										[](const common::TTimedPose2D& p, double t) { return p.t_s < t; });
	const common::TTimedPose2D* best = nullptr;
	if (later != sorted.end()) best = &*later;
	if (later != sorted.begin() && (!best || t_s - std::prev(later)->t_s < best->t_s - t_s)) best = &*std::prev(later);
	if (!best || std::abs(best->t_s - t_s) > max_dt_s) return std::nullopt;
	return mrpt::poses::CPose2D(best->pose);
}

common::TTrajectory2D sortedByTime(common::TTrajectory2D trajectory)
{
	std::sort(trajectory.begin(), trajectory.end(), [](const auto& a, const auto& b) { return a.t_s < b.t_s; });
	return trajectory;
}

mrpt::maps::CSimplePointsMap pointsMap(const TScanPoints2D& scan)
{
	mrpt::maps::CSimplePointsMap map;
	map.reserve(scan.points.size());
	for (const auto& p : scan.points) map.insertPointFast(static_cast<float>(p.x), static_cast<float>(p.y));
	map.mark_as_modified();
	return map;
}

/** Mean capped distance of `later`'s points, placed at `laterInEarlier` in the
 * earlier scan's frame, to the earlier scan's points. */
double pairMisfit(const mrpt::maps::CSimplePointsMap& earlier, const TScanPoints2D& later,
				  const mrpt::poses::CPose2D& laterInEarlier, double truncate_m)
{
	if (later.points.empty()) return truncate_m;
	double sum = 0;
	for (const auto& p : later.points)
	{
		double qx = 0, qy = 0;
		laterInEarlier.composePoint(p.x, p.y, qx, qy);
		const double d2 = earlier.kdTreeClosestPoint2DsqrError(static_cast<float>(qx), static_cast<float>(qy));
		sum += std::min(std::sqrt(d2), truncate_m);
	}
	return sum / static_cast<double>(later.points.size());
}

void summarise(TScanConsistency& result, double clearly_m)
{
	for (const auto& pair : result.pairs)
	{
		result.reference_mean_m += pair.reference_m;
		result.estimate_mean_m += pair.estimate_m;
		if (pair.estimate_m > pair.reference_m + clearly_m) result.estimate_worse.push_back(pair);
		if (pair.estimate_m < pair.reference_m - clearly_m) result.estimate_better.push_back(pair);
	}
	result.reference_mean_m /= static_cast<double>(result.pairs.size());
	result.estimate_mean_m /= static_cast<double>(result.pairs.size());
}
}  // namespace

std::vector<TScanPoints2D> readScanPoints(const std::string& rawlogPath, const std::string& laserLabel,
										  double max_range_m)
{
	const auto scans = io::readRangeScans(rawlogPath);
	std::set<std::string> labels;
	for (const auto& s : scans) labels.insert(s->sensorLabel);
	if (labels.empty()) throw std::runtime_error(rawlogPath + ": the rawlog holds no 2D laser scan");
	if (laserLabel.empty() && labels.size() > 1)
	{
		std::string names;
		for (const auto& l : labels) names += (names.empty() ? "'" : ", '") + l + "'";
		throw std::runtime_error(rawlogPath + ": scans of several lasers (" + names + "): choose one with --laser-label");
	}
	if (!laserLabel.empty() && !labels.count(laserLabel))
		throw std::runtime_error(rawlogPath + ": no scan has the label '" + laserLabel + "'");
	std::vector<TScanPoints2D> out;
	for (const auto& s : scans)
	{
		if (!laserLabel.empty() && s->sensorLabel != laserLabel) continue;
		const common::TRangeData data = common::makeRangeData(*s);
		TScanPoints2D& scan = out.emplace_back();
		scan.t_s = data.t_s;
		for (size_t i = 0; i < data.points.size(); ++i)
			if (data.points.range_m[i] <= max_range_m) scan.points.push_back(data.points.xy[i]);
	}
	return out;
}

TScanConsistency compareScanConsistency(const std::vector<TScanPoints2D>& scans,
										const common::TTrajectory2D& reference, const common::TTrajectory2D& estimate,
										const TScanConsistencyOptions& options)
{
	const common::TTrajectory2D ref = sortedByTime(reference), est = sortedByTime(estimate);
	TScanConsistency result;
	result.scans = scans.size();
	for (size_t i = 1; i < scans.size(); ++i)
	{
		const auto r0 = poseAt(ref, scans[i - 1].t_s, options.max_dt_s), r1 = poseAt(ref, scans[i].t_s, options.max_dt_s);
		const auto e0 = poseAt(est, scans[i - 1].t_s, options.max_dt_s), e1 = poseAt(est, scans[i].t_s, options.max_dt_s);
		if (!r0 || !r1 || !e0 || !e1) continue;
		const mrpt::maps::CSimplePointsMap earlier = pointsMap(scans[i - 1]);
		if (earlier.empty()) continue;
		TScanPairMisfit pair;
		pair.t_s = scans[i].t_s;
		pair.reference_m = pairMisfit(earlier, scans[i], *r1 - *r0, options.truncate_m);
		pair.estimate_m = pairMisfit(earlier, scans[i], *e1 - *e0, options.truncate_m);
		result.pairs.push_back(pair);
	}
	if (result.pairs.empty())
		throw std::runtime_error("scan consistency: no two consecutive scans have poses in both trajectories (within " +
								 std::to_string(options.max_dt_s) + " s)");
	summarise(result, options.clearly_m);
	return result;
}

}  // namespace hslam::eval
