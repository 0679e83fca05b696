#include <hslam/benchdata/leg_dataset.h>
#include <hslam/benchdata/leg_scoring.h>
#include <mrpt/system/datetime.h>

#include <chrono>
#include <cmath>
#include <set>
#include <stdexcept>

namespace hslam::benchdata
{
TLegOutputLevels runLegFilter(const dynamic::CDynamicObjectFilter::TOptions& options,
							  const std::shared_ptr<const dynamic::CLegClassifier>& classifier,
							  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
							  const std::vector<mrpt::poses::CPose2D>& poses)
{
	if (poses.size() != scans.size()) throw std::invalid_argument("runLegFilter: one pose per scan");
	dynamic::CDynamicObjectFilter filter(options, classifier);
	TLegOutputLevels out;
	auto &all = out.detected, &dynamicOnly = out.dynamic, &lateDynamic = out.late;
	all.assign(scans.size(), {});
	dynamicOnly.assign(scans.size(), {});
	lateDynamic.assign(scans.size(), {});
	std::vector<std::vector<std::pair<int, int>>> ids(scans.size());  // per leg: leg track, person track
	std::set<int> dynamicLegIds, dynamicPersonIds;
	for (size_t i = 0; i < scans.size(); ++i)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const auto& frame = filter.process(*scans[i], poses[i], mrpt::Clock::toDouble(scans[i]->timestamp));
		out.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		for (const auto& leg : frame.legs)
		{
			all[i].push_back(leg.segment);
			if (leg.is_dynamic) dynamicOnly[i].push_back(leg.segment);
			ids[i].push_back({leg.leg_track, leg.person_track});
		}
		for (const auto& t : frame.leg_tracks)
			if (t.state == dynamic::ETrackState::dynamic) dynamicLegIds.insert(t.id);
		for (const auto& t : frame.person_tracks)
			if (t.state == dynamic::ETrackState::dynamic) dynamicPersonIds.insert(t.id);
	}
	for (size_t i = 0; i < scans.size(); ++i)
		for (size_t k = 0; k < all[i].size(); ++k)
			if (dynamicLegIds.count(ids[i][k].first) || dynamicPersonIds.count(ids[i][k].second))
				lateDynamic[i].push_back(all[i][k]);
	return out;
}

TLegScore scoreAgainstAnnotations(const TLegsPerScan& reported,
								  const std::vector<std::vector<mrpt::math::TPoint2D>>& labels, double matchRadius_m,
								  double maxRange_m)
{
	TLegScore s;
	for (size_t i = 0; i < reported.size(); ++i)
	{
		++s.scans;
		const auto& legs = reported[i];
		std::vector<bool> used(legs.size(), false);
		for (const auto& a : labels[i])
		{
			++s.annotated;
			const bool inRange = std::hypot(a.x, a.y) < maxRange_m;
			s.annotated_in_range += inRange;
			int best = -1;
			double bestD = matchRadius_m;
			for (size_t j = 0; j < legs.size(); ++j)
			{
				const double d = std::hypot(legs[j].x_m - a.x, legs[j].y_m - a.y);
				if (!used[j] && d <= bestD) bestD = d, best = static_cast<int>(j);
			}
			if (best < 0) continue;
			used[static_cast<size_t>(best)] = true;
			++s.matched;
			s.matched_in_range += inRange;
		}
		for (size_t j = 0; j < legs.size(); ++j)
			if (!used[j]) (inAnnotatedArc({legs[j].x_m, legs[j].y_m}) ? s.arc_unmatched : s.outside_arc)++;
	}
	return s;
}

}  // namespace hslam::benchdata
