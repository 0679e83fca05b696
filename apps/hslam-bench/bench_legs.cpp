/* hslam-bench legs: the leg detector, tracker and map exclusion (libs/dynamic)
 * on real laser data with people, laid out like ../shared/datasets/legs/
 * (see its README.md):
 *   negative_2.rawlog             no people: every detection is false
 *   positive_*_extracted.rawlog   + .scans.csv: annotated leg centroids inside
 *                                 an arc (-15..15 deg, < 5 m); detections
 *                                 outside the arc are not scored
 *   demo_stationary_simple_environment.rawlog   static scanner, people walk:
 *                                 occupied-cell trail with / without exclusion
 * Prints tables, then legs_recall=, legs_false_per_scan=,
 * ghost_cells_reduction= and timing keys. */
#include "bench_common.h"

#include <hslam/common/options_io.h>
#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/dynamic_profiles.h>
#include <hslam/dynamic/occupied_cells.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/matching/CKeyframePointMap.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/grid_rendering.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/slam/CICP.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace hslam::bench
{
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> readScans(const std::string& path)
{
	io::CRawlogReader reader(path);
	io::TRawlogEntry entry;
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	while (reader.next(entry))
	{
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(entry.observation)) scans.push_back(s);
		if (entry.frame)
			for (const auto& o : *entry.frame)
				if (auto s2 = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) scans.push_back(s2);
	}
	return scans;
}

namespace
{
using mrpt::obs::CObservation2DRangeScan;
namespace fs = std::filesystem;


struct TScored
{
	size_t scans = 0, annotated = 0, matched = 0, arc_unmatched = 0, outside_arc = 0;
	size_t annotated_in_range = 0, matched_in_range = 0;
};

/** One CSV line split at commas outside double quotes. */
std::vector<std::string> splitCsv(const std::string& line)
{
	std::vector<std::string> out(1);
	bool quoted = false;
	for (char c : line)
	{
		if (c == '"')
			quoted = !quoted;
		else if (c == ',' && !quoted)
			out.emplace_back();
		else if (c != '\r')
			out.back() += c;
	}
	return out;
}

/** Annotated leg centroids (laser frame) per row of a .scans.csv. */
std::vector<std::vector<mrpt::math::TPoint2D>> readAnnotations(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error(path + ": cannot open");
	std::string line;
	std::getline(in, line);
	const auto header = splitCsv(line);
	const auto col = std::find(header.begin(), header.end(), "annotated_xy");
	if (col == header.end()) throw std::runtime_error(path + ": line 1: no 'annotated_xy' column");
	const size_t k = static_cast<size_t>(col - header.begin());
	std::vector<std::vector<mrpt::math::TPoint2D>> rows;
	for (size_t lineNo = 2; std::getline(in, line); ++lineNo)
	{
		const auto fields = splitCsv(line);
		if (fields.size() != header.size())
			throw std::runtime_error(path + ": line " + std::to_string(lineNo) + ": " +
									 std::to_string(fields.size()) + " fields, header has " +
									 std::to_string(header.size()));
		std::vector<mrpt::math::TPoint2D> legs;
		std::istringstream pairs(fields[k]);
		std::string xy;
		while (std::getline(pairs, xy, ';'))
		{
			mrpt::math::TPoint2D p;
			char comma = 0;
			std::istringstream one(xy);
			if (!(one >> p.x >> comma >> p.y) || comma != ',')
				throw std::runtime_error(path + ": line " + std::to_string(lineNo) + ": annotated_xy '" + xy +
										 "' is not 'x,y'");
			legs.push_back(p);
		}
		rows.push_back(legs);
	}
	return rows;
}

bool inArc(double x, double y)
{
	// leg_tracker's extract_positive_training_clusters arc: bearing strictly
	// within (-15, 15) deg, distance < 5 m (README of the dataset).
	const double b = std::atan2(y, x) * 180 / M_PI;
	return b > -15 && b < 15 && std::hypot(x, y) < 5.0;
}

/** Legs reported for one scan (robot = laser frame here). */
using TLegsPerScan = std::vector<std::vector<dynamic::TLegSegment>>;

/** Matches reported legs to the annotations of each scan, one to one,
 * nearest first within matchRadius_m; reported legs outside the arc are
 * not scored. */
TScored scoreAgainstAnnotations(const TLegsPerScan& reported,
								const std::vector<std::vector<mrpt::math::TPoint2D>>& labels, double matchRadius_m,
								double maxRange_m)
{
	TScored s;
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
			if (!used[j]) (inArc(legs[j].x_m, legs[j].y_m) ? s.arc_unmatched : s.outside_arc)++;
	}
	return s;
}

/** Verdicts of the rule-1 segments nearest to annotated legs the detector missed. */
void countMissReasons(const dynamic::CLegDetector& detector, const std::vector<CObservation2DRangeScan::Ptr>& scans,
					  const std::vector<std::vector<mrpt::math::TPoint2D>>& labels, const TLegsPerScan& detected,
					  double matchRadius_m, std::map<std::string, size_t>& reasons)
{
	for (size_t i = 0; i < scans.size(); ++i)
		for (const auto& a : labels[i])
		{
			bool found = false;
			for (const auto& l : detected[i]) found |= std::hypot(l.x_m - a.x, l.y_m - a.y) <= matchRadius_m;
			if (found) continue;
			std::string why = "no_segment_near";
			double nd = matchRadius_m;
			for (const auto& c : detector.candidates(*scans[i]))
			{
				const double d = std::hypot(c.segment.x_m - a.x, c.segment.y_m - a.y);
				if (d <= nd) nd = d, why = dynamic::toString(c.verdict);
			}
			reasons[why]++;
		}
}

/** Runs the whole filter over a scan sequence; returns, per scan, all
 * detected legs, those flagged dynamic at that scan (causal: what
 * beam_is_dynamic and tracks.csv use) and those whose leg or person track
 * is confirmed dynamic at that scan or later (what the late exclusion
 * removes from the map); adds the time spent to *time_s. */
void runFilter(const dynamic::CDynamicObjectFilter::TOptions& options,
			   const std::vector<CObservation2DRangeScan::Ptr>& scans, const std::vector<mrpt::poses::CPose2D>& poses,
			   TLegsPerScan& all, TLegsPerScan& dynamicOnly, TLegsPerScan& lateDynamic, double* time_s)
{
	dynamic::CDynamicObjectFilter filter(options);
	all.assign(scans.size(), {});
	dynamicOnly.assign(scans.size(), {});
	lateDynamic.assign(scans.size(), {});
	std::vector<std::vector<std::pair<int, int>>> ids(scans.size());  // per leg: leg track, person track
	std::set<int> dynamicLegIds, dynamicPersonIds;
	for (size_t i = 0; i < scans.size(); ++i)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const auto& frame = filter.process(*scans[i], poses[i], mrpt::Clock::toDouble(scans[i]->timestamp));
		*time_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		all[i] = frame.legs;
		for (size_t k = 0; k < frame.legs.size(); ++k)
		{
			if (frame.leg_is_dynamic[k]) dynamicOnly[i].push_back(frame.legs[k]);
			ids[i].push_back({frame.leg_track[k], frame.person_track[k]});
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
}

/** ICP odometry of one sensor (negative_2 has no odometry and no tf): the
 * robot motion the tracker compensates. Laser frame = robot frame. Each
 * scan is matched against the world points of recent keyframes
 * (matching::CKeyframePointMap, as MRPT's icp-slam does), seeded by the
 * previous motion (matching only the previous scan drifts like a random
 * walk: 1.70 instead of 1.63 confirmed false legs per scan). */
std::vector<mrpt::poses::CPose2D> icpPoses(const std::vector<CObservation2DRangeScan::Ptr>& scans)
{
	mrpt::slam::CICP icp;
	icp.options.maxIterations = 200;
	icp.options.thresholdDist = 0.3;
	icp.options.thresholdAng = 2 * M_PI / 180;
	icp.options.ALFA = 0.5;
	icp.options.smallestThresholdDist = 0.02;
	std::vector<mrpt::poses::CPose2D> poses(scans.size());
	mrpt::poses::CPose2D lastDelta;
	matching::CKeyframePointMap::TOptions kfOptions;
	kfOptions.insertion_distance_m = 0.3;
	kfOptions.insertion_angle_rad = 10 * M_PI / 180;
	kfOptions.max_keyframes = 20;
	matching::CKeyframePointMap keyframes(kfOptions);
	for (size_t i = 0; i < scans.size(); ++i)
	{
		mrpt::maps::CSimplePointsMap current;
		current.insertObservation(*scans[i]);
		if (i > 0)
		{
			const mrpt::poses::CPose2D guess = poses[i - 1] + lastDelta;
			const auto pdf = icp.Align(&keyframes.reference(guess), &current, guess);
			poses[i] = pdf->getMeanVal();
			lastDelta = poses[i] - poses[i - 1];
		}
		if (keyframes.empty() || keyframes.wantsKeyframe(poses[i]))
		{
			std::vector<mrpt::math::TPoint2D> points(current.size());
			for (size_t k = 0; k < current.size(); ++k) current.getPoint(k, points[k].x, points[k].y);
			keyframes.addKeyframe(poses[i], points);
		}
	}
	return poses;
}

struct TTrailResult
{
	size_t occupied_without = 0, occupied_with = 0, trail_without = 0, trail_with = 0, static_cells = 0;
	size_t scans = 0, masked_beams = 0, person_tracks = 0;
	double filter_s = 0;
};

/** Static scanner: the per-beam median range over the whole log is the
 * background (people pass, walls stay); cells it marks occupied are the
 * static structure, any other occupied cell is a trail. */
CObservation2DRangeScan medianScan(const std::vector<CObservation2DRangeScan::Ptr>& scans)
{
	CObservation2DRangeScan median = *scans.front();
	for (size_t b = 0; b < median.getScanSize(); ++b)
	{
		std::vector<float> r;
		for (const auto& s : scans)
			if (s->getScanSize() == median.getScanSize() && s->getScanRangeValidity(b)) r.push_back(s->getScanRange(b));
		// Valid in most scans: the median of the valid readings; else no return.
		const bool valid = r.size() * 2 > scans.size();
		if (valid)
		{
			std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
			median.setScanRange(b, r[r.size() / 2]);
		}
		median.setScanRangeValidity(b, valid);
	}
	return median;
}

TTrailResult trailOnStaticLog(const dynamic::CDynamicObjectFilter::TOptions& options, const std::string& rawlog,
							  const std::string& pngPath)
{
	const auto scans = readScans(rawlog);
	if (scans.empty()) throw std::runtime_error(rawlog + ": no 2D scans");
	maps::CLaserGridInserter::TOptions laser;
	laser.max_range_m = 5.5;  // the demo laser reaches 5.6 m
	maps::CLaserGridInserter inserter(laser);
	maps::CTiledOccupancyGrid without, with, reference;
	const mrpt::poses::CPose2D origin;
	dynamic::CDynamicObjectFilter filter(options);
	TTrailResult r;
	for (const auto& s : scans)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const auto& frame = filter.process(*s, origin, mrpt::Clock::toDouble(s->timestamp));
		r.filter_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		inserter.insert(without, origin, *s);
		inserter.insert(with, origin, *s, &frame.beam_is_dynamic);
		dynamic::undoOccupiedHits(with, frame.retro_clear_world, inserter.options().occupied_probability);
		r.masked_beams += frame.dynamicBeams();
		++r.scans;
	}
	r.person_tracks = static_cast<size_t>(filter.personTracker().createdTracks());
	const auto background = medianScan(scans);
	for (int k = 0; k < 20; ++k) inserter.insert(reference, origin, background);
	r.static_cells = dynamic::occupiedCells(reference).size();
	r.occupied_without = dynamic::occupiedCells(without).size();
	r.occupied_with = dynamic::occupiedCells(with).size();
	r.trail_without = dynamic::cellsNotIn(without, reference, 1).size();
	r.trail_with = dynamic::cellsNotIn(with, reference, 1).size();

	saveExclusionComparison(without, with, 3, pngPath);
	return r;
}

}  // namespace

namespace
{
double ratio(size_t a, size_t b) { return static_cast<double>(a) / static_cast<double>(std::max<size_t>(1, b)); }

void addTo(TScored& total, const TScored& s)
{
	total.scans += s.scans;
	total.annotated += s.annotated;
	total.matched += s.matched;
	total.arc_unmatched += s.arc_unmatched;
	total.annotated_in_range += s.annotated_in_range;
	total.matched_in_range += s.matched_in_range;
}

std::vector<fs::path> positiveFiles(const std::string& dataDir)
{
	std::vector<fs::path> positives;
	for (const auto& e : fs::directory_iterator(dataDir))
	{
		const std::string name = e.path().filename().string();
		if (name.rfind("positive_", 0) == 0 && e.path().extension() == ".rawlog" &&
			name.find("_extracted") != std::string::npos)
			positives.push_back(e.path());
	}
	std::sort(positives.begin(), positives.end());
	return positives;
}
}  // namespace

dynamic::CDynamicObjectFilter::TOptions loadDynamicOptions(const std::string& profileIni, const std::string& configFile)
{
	dynamic::CDynamicObjectFilter::TOptions options;
	mrpt::config::CConfigFileMemory profile(profileIni);
	common::loadOptions(options, profile, "dynamic_objects");
	if (!configFile.empty())
	{
		if (!fs::exists(configFile)) throw std::runtime_error(configFile + ": no such file");
		mrpt::config::CConfigFile cfg(configFile);
		common::loadOptions(options, cfg, "dynamic_objects");
	}
	return options;
}

int runLegsSuite(const std::string& dataDir, const std::string& outDir, const std::string& configFile)
{
	const auto options = loadDynamicOptions(dynamic::kHokuyoLegsProfileIni, configFile);
	if (!configFile.empty()) std::cout << "Options of " << configFile << " [dynamic_objects] applied on top of:\n";
	const dynamic::CLegDetector detector(options.detector);
	std::cout << "Profile for 0.35 deg Hokuyo scans (thesis defaults otherwise):\n" << dynamic::kHokuyoLegsProfileIni << "\n";
	const double matchRadius_m = 0.20;
	double filter_s = 0, detect_s = 0;
	size_t filterScans = 0, detectScans = 0;

	// 1. No people: every leg is false. Single-scan detector, and the filter
	// (legs flagged dynamic) with the robot motion from scan-to-keyframe-map ICP.
	std::map<std::string, std::vector<CObservation2DRangeScan::Ptr>> bySensor;
	for (const auto& s : readScans(dataDir + "/negative_2.rawlog")) bySensor[s->sensorLabel].push_back(s);
	size_t negScans = 0, negLegs = 0, negDynamic = 0, negLate = 0;
	std::cout << "negative_2 (no people; robot motion by ICP per sensor)\n"
			  << "  sensor        scans  legs/scan  dynamic legs/scan  (late)  ICP path (m)\n";
	for (const auto& [label, scans] : bySensor)
	{
		const auto poses = icpPoses(scans);
		double path_m = 0;
		for (size_t i = 1; i < poses.size(); ++i) path_m += poses[i].distanceTo(poses[i - 1]);
		const auto t0 = std::chrono::steady_clock::now();
		for (const auto& scan : scans) detector.detect(*scan);
		detect_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		detectScans += scans.size();
		TLegsPerScan all, dyn, late;
		runFilter(options, scans, poses, all, dyn, late, &filter_s);
		filterScans += scans.size();
		size_t legs = 0, dynLegs = 0, lateLegs = 0;
		for (size_t i = 0; i < scans.size(); ++i)
			legs += all[i].size(), dynLegs += dyn[i].size(), lateLegs += late[i].size();
		std::cout << "  " << std::left << std::setw(12) << label << std::right << std::setw(7) << scans.size()
				  << std::setw(11) << std::fixed << std::setprecision(3) << ratio(legs, scans.size()) << std::setw(19)
				  << ratio(dynLegs, scans.size()) << std::setw(16) << ratio(lateLegs, scans.size()) << std::setw(14)
				  << std::setprecision(1) << path_m << "\n";
		negScans += scans.size();
		negLegs += legs;
		negDynamic += dynLegs;
		negLate += lateLegs;
	}

	// 2. Annotated legs inside the arc (static scanner: identity poses).
	TScored detTotal, dynTotal, lateTotal;
	std::map<std::string, size_t> reasons;
	std::cout << std::setprecision(3) << "\npositive_*_extracted (annotated legs in the arc -15..15 deg, < 5 m; match radius "
			  << matchRadius_m << " m)\n"
			  << "  file                    scans  legs  detected  recall  flagged dynamic  recall  (late)  in-arc unmatched\n";
	for (const auto& p : positiveFiles(dataDir))
	{
		const auto scans = readScans(p.string());
		const std::string csv = (p.parent_path() / (p.stem().string() + ".scans.csv")).string();
		const auto labels = readAnnotations(csv);
		if (labels.size() != scans.size())
			throw std::runtime_error(csv + ": " + std::to_string(labels.size()) + " rows but " + p.string() +
									 " has " + std::to_string(scans.size()) + " scans");
		TLegsPerScan all, dyn, late;
		runFilter(options, scans, std::vector<mrpt::poses::CPose2D>(scans.size()), all, dyn, late, &filter_s);
		filterScans += scans.size();
		const auto det = scoreAgainstAnnotations(all, labels, matchRadius_m, options.detector.max_range_m);
		const auto dy = scoreAgainstAnnotations(dyn, labels, matchRadius_m, options.detector.max_range_m);
		const auto lt = scoreAgainstAnnotations(late, labels, matchRadius_m, options.detector.max_range_m);
		addTo(lateTotal, lt);
		countMissReasons(detector, scans, labels, all, matchRadius_m, reasons);
		std::cout << "  " << std::left << std::setw(22) << p.stem().string() << std::right << std::setw(7)
				  << det.scans << std::setw(6) << det.annotated << std::setw(10) << det.matched << std::setw(8)
				  << ratio(det.matched, det.annotated) << std::setw(17) << dy.matched << std::setw(8)
				  << ratio(dy.matched, dy.annotated) << std::setw(8) << ratio(lt.matched, lt.annotated) << std::setw(18)
				  << det.arc_unmatched << "\n";
		addTo(detTotal, det);
		addTo(dynTotal, dy);
	}
	std::cout << "  missed by the detector, verdict of the nearest segment:";
	for (const auto& [why, n] : reasons) std::cout << " " << why << "=" << n;
	std::cout << "\n";

	// 3. Static scanner, people walking: trail of occupied cells.
	fs::create_directories(outDir);
	const std::string png = outDir + "/legs_demo_maps.png";
	const auto trail = trailOnStaticLog(options, dataDir + "/demo_stationary_simple_environment.rawlog", png);
	filter_s += trail.filter_s;
	filterScans += trail.scans;
	const double reduction = trail.trail_without ? 1.0 - ratio(trail.trail_with, trail.trail_without) : 0.0;
	std::cout << "\ndemo_stationary_simple_environment (" << trail.scans << " scans, static scanner)\n"
			  << "  static cells (median background): " << trail.static_cells << "\n"
			  << "  occupied cells without / with exclusion: " << trail.occupied_without << " / "
			  << trail.occupied_with << "\n"
			  << "  trail cells (occupied, > 1 cell from static structure) without / with: " << trail.trail_without
			  << " / " << trail.trail_with << "\n"
			  << "  person tracks created: " << trail.person_tracks
			  << ", masked beams per scan: " << ratio(trail.masked_beams, trail.scans) << "\n"
			  << "  maps side by side: " << png << "\n\n";

	// Final keys: the leg detector (what the issue scores: detections per
	// scan); the filter's dynamic flags (detection + tracking + motion) as
	// legs_dynamic_*.
	std::cout << std::setprecision(4) << "legs_negative_scans=" << negScans << "\nlegs_annotated=" << detTotal.annotated
			  << "\nlegs_recall_within_max_range=" << ratio(detTotal.matched_in_range, detTotal.annotated_in_range)
			  << "\nlegs_arc_unmatched_per_scan=" << ratio(detTotal.arc_unmatched, detTotal.scans)
			  << "\nlegs_dynamic_recall=" << ratio(dynTotal.matched, dynTotal.annotated)
			  << "\nlegs_dynamic_false_per_scan=" << ratio(negDynamic, negScans)
			  << "\nlegs_late_dynamic_recall=" << ratio(lateTotal.matched, lateTotal.annotated)
			  << "\nlegs_late_dynamic_false_per_scan=" << ratio(negLate, negScans)
			  << "\nghost_cells_without=" << trail.trail_without << "\nghost_cells_with=" << trail.trail_with
			  << "\ndetect_us_per_scan_768_beams=" << 1e6 * detect_s / std::max<size_t>(1, detectScans)
			  << "\nfilter_us_per_scan=" << 1e6 * filter_s / std::max<size_t>(1, filterScans)
			  << "\nlegs_recall=" << ratio(detTotal.matched, detTotal.annotated)
			  << "\nlegs_false_per_scan=" << ratio(negLegs, negScans) << "\nghost_cells_reduction=" << reduction
			  << "\n";
	return 0;
}

}  // namespace hslam::bench
