/* hslam-bench legs: the leg detector, tracker and map exclusion (libs/dynamic)
 * on real laser data with people, laid out like ../shared/datasets/legs/
 * (see its README.md):
 *   negative_2.rawlog             no people: every detection is false
 *   positive_*_extracted.rawlog   + .scans.csv: annotated leg centroids inside
 *                                 an arc (-15..15 deg, < 5 m); detections
 *                                 outside the arc are not scored
 *   demo_stationary_simple_environment.rawlog   static scanner, people walk:
 *                                 occupied-cell trail with / without exclusion
 * Two methods: the thesis rules (Hokuyo profile) and the learned classifier
 * (CLegClassifier), the latter scored by cross-validation: each recording
 * is scored with a forest trained on the other folds only (leg_training.h).
 * Three output levels each: every detected leg; legs flagged dynamic when
 * seen (causal); legs whose track is confirmed dynamic at any time (late:
 * what the batch map excludes). Prints tables, then legs_recall=,
 * legs_false_per_scan= (learned, late), ghost_cells_reduction= (learned)
 * and the other levels' and timing keys. */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/dynamic_profiles.h>
#include <hslam/benchdata/leg_dataset.h>
#include <hslam/benchdata/leg_scoring.h>
#include <hslam/benchdata/leg_training.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/io/rawlog_scans.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/grid_rendering.h>
#include <hslam/matching/icp_odometry.h>
#include <hslam/slam/CDynamicMappingStage.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>

namespace hslam::bench
{
namespace
{
using mrpt::obs::CObservation2DRangeScan;
namespace fs = std::filesystem;

using benchdata::TLegsPerScan;
using TScored = benchdata::TLegScore;

using TClassifierPtr = std::shared_ptr<const dynamic::CLegClassifier>;



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

TTrailResult trailOnStaticLog(const dynamic::CDynamicObjectFilter::TOptions& options, const TClassifierPtr& classifier,
							  const std::string& rawlog, const std::string& pngPath)
{
	const auto scans = io::readRangeScans(rawlog);
	if (scans.empty()) throw std::runtime_error(rawlog + ": no 2D scans");
	maps::CLaserGridInserter::TOptions laser;
	laser.max_range_m = 5.5;  // the demo laser reaches 5.6 m
	maps::CLaserGridInserter inserter(laser);
	maps::CTiledOccupancyGrid without, with, reference;
	const mrpt::poses::CPose2D origin;
	slam::CDynamicMappingStage stage(inserter, std::make_unique<dynamic::CDynamicObjectFilter>(options, classifier));
	stage.addGrid(with);
	TTrailResult r;
	for (const auto& s : scans)
	{
		const auto t0 = std::chrono::steady_clock::now();
		const auto& update = stage.filterScan(*s, origin, mrpt::Clock::toDouble(s->timestamp));
		r.filter_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		inserter.insert(without, origin, *s);
		stage.insertScan(0, *s, origin, update);  // late exclusions, then the scan with its mask
		r.masked_beams += stage.filter()->lastFrame().dynamicBeams();
		++r.scans;
	}
	r.person_tracks = static_cast<size_t>(stage.filter()->personTracker().createdTracks());
	const auto background = medianScan(scans);
	for (int k = 0; k < 20; ++k) inserter.insert(reference, origin, background);
	r.static_cells = benchdata::occupiedCells(reference).size();
	r.occupied_without = benchdata::occupiedCells(without).size();
	r.occupied_with = benchdata::occupiedCells(with).size();
	// Trail = false occupied cells against the static structure (map_scoring.h).
	const auto staticStructure = benchdata::cellClassesOf(reference);
	r.trail_without = benchdata::falseOccupiedCells(benchdata::cellClassesOf(without), staticStructure, without.observedBounds()).size();
	r.trail_with = benchdata::falseOccupiedCells(benchdata::cellClassesOf(with), staticStructure, with.observedBounds()).size();

	saveExclusionComparison(without, with, 3, pngPath);
	return r;
}

}  // namespace

namespace
{
double ratio(size_t a, size_t b) { return static_cast<double>(a) / static_cast<double>(std::max<size_t>(1, b)); }

/** Scores of one output level over the whole folder. */
struct TLevel
{
	size_t annotated = 0, matched = 0, false_legs = 0, negative_scans = 0, arc_unmatched = 0;
	double recall() const { return ratio(matched, annotated); }
	double falsePerScan() const { return ratio(false_legs, negative_scans); }
};

/** The three output levels of the filter: every detected leg, legs flagged
 * dynamic when seen (causal), legs whose track is confirmed at any time
 * (what late exclusion removes from the map). */
struct TMethodResult
{
	TLevel detected, dynamic, late;
	double filter_s = 0;
	size_t filter_scans = 0;
	std::map<std::string, size_t> miss_reasons;
};

void addPositive(TLevel& level, const TScored& s)
{
	level.annotated += s.annotated;
	level.matched += s.matched;
	level.arc_unmatched += s.arc_unmatched;
}

void addNegative(TLevel& level, const TLegsPerScan& reported)
{
	level.negative_scans += reported.size();
	for (const auto& legs : reported) level.false_legs += legs.size();
}

/** The per-part table of evaluateMethod; its header (printed there, as
 * published) names the columns, not their edges. A part with people shows
 * annotated legs and, per level, matched legs (recall); a part without people
 * the false legs per scan of each level. */
CReportTable partTable()
{
	return CReportTable(std::cout, {{"", 2, true},
									{"part", 24, true},
									{"scans", 6},
									{"annotated", 11},
									{"detected (recall)", 19},
									{"dynamic (recall)", 18},
									{"late (recall)", 16}});
}

/** `matched` right-aligned in `width`, then its recall: "   12 (0.923)". */
std::string matchedCell(const TScored& s, int width)
{
	return padLeft(std::to_string(s.matched), width) + " (" + fixed(ratio(s.matched, s.annotated), 3) + ")";
}

/** Scores a part with people at the three levels, adds them to `r` (and the
 * detector's misses to r.miss_reasons); returns the row's level cells. */
std::vector<std::string> scorePositivePart(const benchdata::TLegDataPart& part,
										   const dynamic::CDynamicObjectFilter::TOptions& options,
										   const TClassifierPtr& classifier, const benchdata::TLegOutputLevels& levels,
										   TMethodResult& r)
{
	constexpr double kMatchRadius_m = 0.20;
	const double maxRange_m = options.detector.max_range_m;
	const auto det = benchdata::scoreAgainstAnnotations(levels.detected, part.annotations, kMatchRadius_m, maxRange_m);
	const auto dy = benchdata::scoreAgainstAnnotations(levels.dynamic, part.annotations, kMatchRadius_m, maxRange_m);
	const auto lt = benchdata::scoreAgainstAnnotations(levels.late, part.annotations, kMatchRadius_m, maxRange_m);
	addPositive(r.detected, det);
	addPositive(r.dynamic, dy);
	addPositive(r.late, lt);
	const dynamic::CLegDetector detector(options.detector, classifier);
	countMissReasons(detector, part.scans, part.annotations, levels.detected, kMatchRadius_m, r.miss_reasons);
	return {std::to_string(det.annotated), matchedCell(det, 11), matchedCell(dy, 10), matchedCell(lt, 8)};
}

/** Adds a part without people to `r`; returns the row's level cells (false
 * legs per scan of the part). */
std::vector<std::string> scoreNegativePart(const benchdata::TLegOutputLevels& levels, TMethodResult& r)
{
	TLevel d, y, l;
	addNegative(d, levels.detected);
	addNegative(y, levels.dynamic);
	addNegative(l, levels.late);
	addNegative(r.detected, levels.detected);
	addNegative(r.dynamic, levels.dynamic);
	addNegative(r.late, levels.late);
	return {"-", fixed(d.falsePerScan(), 3), fixed(y.falsePerScan(), 3), fixed(l.falsePerScan(), 3)};
}

/** Runs the filter over every part; `classifierOf(part index)` gives the
 * classifier to use (null: the rules); negative parts use the ICP poses of
 * `negativePoses` (by part index), positive parts a static scanner. */
TMethodResult evaluateMethod(const std::string& title, const dynamic::CDynamicObjectFilter::TOptions& options,
							 const std::vector<benchdata::TLegDataPart>& parts,
							 const std::function<TClassifierPtr(size_t)>& classifierOf,
							 const std::map<size_t, std::vector<mrpt::poses::CPose2D>>& negativePoses)
{
	TMethodResult r;
	std::cout << "\n" << title << "\n"
			  << "  part                     scans  annotated   detected (recall)   dynamic (recall)   late (recall)\n"
			  << "                                  / false legs per scan on parts without people\n";
	const CReportTable table = partTable();
	for (size_t i = 0; i < parts.size(); ++i)
	{
		const auto& part = parts[i];
		const auto classifier = classifierOf(i);
		const auto poses = part.has_people ? std::vector<mrpt::poses::CPose2D>(part.scans.size()) : negativePoses.at(i);
		const auto levels = benchdata::runLegFilter(options, classifier, part.scans, poses);
		r.filter_s += levels.seconds;
		r.filter_scans += part.scans.size();
		std::vector<std::string> cells{"", part.name, std::to_string(part.scans.size())};
		const auto scored =
			part.has_people ? scorePositivePart(part, options, classifier, levels, r) : scoreNegativePart(levels, r);
		cells.insert(cells.end(), scored.begin(), scored.end());
		table.printRow(cells);
	}
	std::cout << "  missed by the detector, verdict of the nearest candidate:";
	for (const auto& [why, n] : r.miss_reasons) std::cout << " " << why << "=" << n;
	std::cout << "\n";
	return r;
}

void printLevels(const std::string& method, const TMethodResult& r)
{
	const std::pair<const char*, const TLevel*> rows[] = {
		{"detected", &r.detected}, {"dynamic (causal)", &r.dynamic}, {"dynamic (late)", &r.late}};
	// The summary's header is printed by the caller (runLegsSuite).
	const CReportTable table(std::cout, {{"", 2, true}, {"method", 26, true}, {"output", 18, true}, {"recall", 8},
										 {"false legs per scan", 20}});
	for (const auto& [name, level] : rows)
		table.printRow({"", method, name, fixed(level->recall(), 3), fixed(level->falsePerScan(), 3)});
}

TTrailResult printTrail(const std::string& title, const dynamic::CDynamicObjectFilter::TOptions& options,
						const TClassifierPtr& classifier, const std::string& rawlog, const std::string& png)
{
	const auto trail = trailOnStaticLog(options, classifier, rawlog, png);
	// The header (printed by runLegsSuite, as published) names the columns, not their edges.
	const CReportTable table(std::cout, {{"", 2, true},
										 {"method", 26, true},
										 {"static", 8},
										 {"occupied w/o / with", 0},
										 {"trail w/o / with", 0},
										 {"persons", 10},
										 {"masked/scan", 12},
										 {"image", 0}});
	const auto pair = [](size_t without, size_t with, int width)
	{ return padLeft(std::to_string(without), width) + " / " + std::to_string(with); };
	table.printRow({"", title, std::to_string(trail.static_cells), pair(trail.occupied_without, trail.occupied_with, 14),
					pair(trail.trail_without, trail.trail_with, 12), std::to_string(trail.person_tracks),
					fixed(ratio(trail.masked_beams, trail.scans), 1), "   " + png});
	return trail;
}

/** Robot poses of the parts without people (no odometry, no tf): ICP per sensor. */
std::map<size_t, std::vector<mrpt::poses::CPose2D>> negativePartPoses(const std::vector<benchdata::TLegDataPart>& parts)
{
	std::map<size_t, std::vector<mrpt::poses::CPose2D>> negativePoses;
	std::cout << "\nRobot motion of the parts without people (no odometry, no tf): ICP per sensor\n";
	const CReportTable table(std::cout, {{"", 2, true}, {"part", 24, true}, {"path", 0}});
	for (size_t i = 0; i < parts.size(); ++i)
		if (!parts[i].has_people)
		{
			negativePoses[i] = matching::icpOdometry(parts[i].scans);
			double path_m = 0;
			for (size_t k = 1; k < negativePoses[i].size(); ++k)
				path_m += negativePoses[i][k].distanceTo(negativePoses[i][k - 1]);
			table.printRow({"", parts[i].name, fixed(path_m, 1) + " m"});
		}
	return negativePoses;
}

/** The suite's key=value lines. */
void printLegsKeys(const TMethodResult& rules, const TMethodResult& learned, const TTrailResult& rulesTrail,
				   const TTrailResult& trail)
{
	const double reduction = trail.trail_without ? 1.0 - ratio(trail.trail_with, trail.trail_without) : 0.0;
	// Final keys: the filter with the learned classifier, cross-validated, at
	// the level the batch map uses (a leg is a person's if its track is
	// confirmed dynamic at any time: late exclusion); the causal level (as
	// known at the scan) and the rules for comparison.
	const double filter_s = learned.filter_s + trail.filter_s;
	const size_t filterScans = learned.filter_scans + trail.scans;
	std::cout << "\n";
	CKeyValueLines(std::cout, 4)("legs_negative_scans", learned.detected.negative_scans)(
		"legs_annotated", learned.detected.annotated)("legs_rules_detected_recall", rules.detected.recall())(
		"legs_rules_detected_false_per_scan", rules.detected.falsePerScan())(
		"legs_rules_dynamic_recall", rules.dynamic.recall())(
		"legs_rules_dynamic_false_per_scan", rules.dynamic.falsePerScan())(
		"legs_detected_recall", learned.detected.recall())("legs_detected_false_per_scan", learned.detected.falsePerScan())(
		"legs_causal_recall", learned.dynamic.recall())("legs_causal_false_per_scan", learned.dynamic.falsePerScan())(
		"ghost_cells_rules_without", rulesTrail.trail_without)("ghost_cells_rules_with", rulesTrail.trail_with)(
		"ghost_cells_without", trail.trail_without)("ghost_cells_with", trail.trail_with)(
		"filter_us_per_scan", 1e6 * filter_s / std::max<size_t>(1, filterScans))(
		"filter_rules_us_per_scan_labelled", 1e6 * rules.filter_s / std::max<size_t>(1, rules.filter_scans))(
		"filter_learned_us_per_scan_labelled", 1e6 * learned.filter_s / std::max<size_t>(1, learned.filter_scans))(
		"filter_learned_vs_rules_time_ratio", learned.filter_s / std::max(1e-12, rules.filter_s))(
		"legs_recall", learned.late.recall())("legs_false_per_scan", learned.late.falsePerScan())(
		"ghost_cells_reduction", reduction);
}
}  // namespace

int runLegsSuite(const std::string& dataDir, const std::string& outDir, const std::string& configFile)
{
	// The profiles are the INI files of config_ini/ (run from the repository root).
	const std::string rulesIni = "config_ini/hslam-legs-hokuyo-rules.ini", learnedIni = "config_ini/hslam-legs-hokuyo.ini";
	const auto rulesOptions = dynamic::loadDynamicOptions({rulesIni, configFile});
	auto learnedOptions = dynamic::loadDynamicOptions({learnedIni, configFile});
	std::cout << "Profiles for 0.35 deg Hokuyo scans (thesis defaults otherwise): [dynamic_objects] of " << rulesIni
			  << " (rules), " << learnedIni << " (learned classifier)\n";
	if (!configFile.empty()) std::cout << "then the [dynamic_objects] keys of " << configFile << "\n";

	const auto parts = benchdata::loadLegDataset(dataDir);
	const auto negativePoses = negativePartPoses(parts);

	// 1. The rule set (thesis 4.7.1 with the Hokuyo profile).
	const auto rules = evaluateMethod("Thesis rules (CLegDetector rules, Hokuyo profile)", rulesOptions, parts,
									  [](size_t) { return TClassifierPtr(); }, negativePoses);

	// 2. The learned classifier, cross-validated: each part is scored with a
	// forest that never saw it nor its fold (legs_cross_validation.h).
	const auto trainOptions = dynamic::loadLegTrainOptions(configFile);
	const auto folds = benchdata::trainFoldClassifiers(parts, learnedOptions.detector, trainOptions);
	const auto learned = evaluateMethod(
		"Learned classifier, " + std::to_string(folds.models.size()) + "-fold cross-validated (" + folds.description + ")",
		learnedOptions, parts, [&](size_t i) { return folds.models[static_cast<size_t>(folds.fold_of_part[i])]; },
		negativePoses);

	std::cout << "\nSummary (recall of annotated legs; false legs per scan on the parts without people)\n"
			  << "  method                    output             recall  false legs per scan\n";
	printLevels("thesis rules", rules);
	printLevels("learned (cross-validated)", learned);

	// 3. Static scanner, people walking: trail of occupied cells. The learned
	// filter uses a forest trained on every labelled part (the demo has none).
	fs::create_directories(outDir);
	const auto fullModel = benchdata::trainOnAll(parts, learnedOptions.detector, trainOptions);
	std::cout << "\ndemo_stationary_simple_environment (static scanner, people walking)\n"
			  << "  method                    static  occupied w/o / with  trail w/o / with  persons  masked/scan\n";
	const std::string demo = dataDir + "/demo_stationary_simple_environment.rawlog";
	const auto rulesTrail = printTrail("thesis rules", rulesOptions, nullptr, demo, outDir + "/legs_demo_maps_rules.png");
	const auto trail = printTrail("learned", learnedOptions, fullModel, demo, outDir + "/legs_demo_maps.png");

	printLegsKeys(rules, learned, rulesTrail, trail);
	return 0;
}

}  // namespace hslam::bench
