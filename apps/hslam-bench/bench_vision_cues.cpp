/* hslam-bench vision, part 4: the camera's moving-object cues as motion
 * evidence for the laser leg tracks ([dynamic_objects] camera_cue_evidence,
 * CCameraCueBuffer.h), off and on, in the batch pipeline
 * (config_ini/hslam-default.ini, [vision] scaled to 320 x 240) on the
 * simulated camera sample (rawlog_samples/camera: two walking people, a
 * forward camera at 5 Hz). Scored against the simulator's truth, in the
 * robot frame of each scan (true pose from ground_truth.tum), within 0.5 m:
 *   recall      share of (scan, person) with >= 3 leg beams that have a
 *               dynamic person track on them (also only those in the
 *               camera's field of view, where a cue can help);
 *   first conf. mean delay (s) from a person's first visible scan to its
 *               first covered one;
 *   false       person (leg) tracks ever dynamic that were never within
 *               0.5 m of a true person. */
#include "bench_csv.h"
#include "bench_report.h"
#include "bench_vision.h"

#include <hslam/common/config_overrides.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/rawlog_scans.h>
#include <hslam/slam/CMappingPipeline.h>
#include <hslam/vision/observation_image.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

namespace hslam::bench
{
namespace
{
constexpr double kMatch_m = 0.5;
constexpr size_t kMinBeams = 3;

struct TCueTruth
{
	std::vector<mrpt::poses::CPose2D> poses;  //!< per laser scan
	std::vector<double> t_s;  //!< per laser scan
	std::vector<std::map<int, mrpt::math::TPoint2D>> people;  //!< per scan: person -> world position
	std::vector<std::map<int, size_t>> beams;  //!< per scan: person -> leg beams
	double scan_period_s = 0.1;
};

TCueTruth loadCueTruth(const std::string& dir)
{
	TCueTruth t;
	const auto tum = common::readTumFile(dir + "/ground_truth.tum");
	for (const auto& p : tum) t.poses.emplace_back(p.pose), t.t_s.push_back(p.t_s);
	const size_t n = t.poses.size();
	if (n < 2) throw std::runtime_error(dir + "/ground_truth.tum: fewer than 2 poses");
	t.scan_period_s = (tum.back().t_s - tum.front().t_s) / static_cast<double>(n - 1);
	t.people.resize(n);
	t.beams.resize(n);
	const std::string peopleFile = dir + "/people.csv.gz", labelsFile = dir + "/beam_labels.csv.gz";
	for (const auto& row : readCsv(peopleFile))
	{
		const auto s = static_cast<size_t>(number(row, "scan", peopleFile));
		if (s < n)
			t.people[s][static_cast<int>(number(row, "person", peopleFile))] = {number(row, "x_m", peopleFile),
																				 number(row, "y_m", peopleFile)};
	}
	for (const auto& row : readCsv(labelsFile))
	{
		const auto s = static_cast<size_t>(number(row, "scan", labelsFile));
		if (s < n && row.at("kind") == "person_leg") t.beams[s][static_cast<int>(number(row, "object", labelsFile))]++;
	}
	return t;
}

struct TCueScore
{
	size_t visible = 0, covered = 0, visible_in_view = 0, covered_in_view = 0;
	size_t person_tracks = 0, false_person_tracks = 0, leg_tracks = 0, false_leg_tracks = 0;
	double first_delay_s = 0;  //!< mean over people seen
	size_t cue_legs = 0, cues = 0;
	size_t cues_on_people = 0;  //!< cue regions whose bearing range (+ margin) holds a true person
};

/** A true person in the robot frame of scan s. */
mrpt::math::TPoint2D inRobotFrame(const TCueTruth& t, size_t s, const mrpt::math::TPoint2D& world)
{
	return t.poses[s].inverseComposePoint(world);
}

bool nearAnyPerson(const TCueTruth& t, size_t s, double x, double y)
{
	for (const auto& [id, w] : t.people[s])
	{
		const auto r = inRobotFrame(t, s, w);
		if (std::hypot(r.x - x, r.y - y) <= kMatch_m) return true;
	}
	return false;
}

/** Tracks ever dynamic, and those of them never near a true person. */
void scoreFalseTracks(const std::vector<dynamic::TTrackRow>& rows, const TCueTruth& t, TCueScore& sc)
{
	std::map<std::pair<std::string, int>, bool> real;  // (kind, id) -> ever near a person
	for (const auto& r : rows)
	{
		if (r.track.state != dynamic::ETrackState::dynamic || r.scan >= t.poses.size()) continue;
		bool& near = real[{r.kind, r.track.id}];
		near = near || nearAnyPerson(t, r.scan, r.x_robot_m, r.y_robot_m);
	}
	for (const auto& [key, near] : real)
	{
		const bool person = key.first == "person";
		(person ? sc.person_tracks : sc.leg_tracks)++;
		if (!near) (person ? sc.false_person_tracks : sc.false_leg_tracks)++;
	}
}

/** The camera's horizontal field of view seen from its position on the robot. */
struct TCameraView
{
	double x_m = 0, y_m = 0, half_fov_rad = 0;
	bool contains(const mrpt::math::TPoint2D& p) const
	{
		return std::abs(std::atan2(p.y - y_m, p.x - x_m)) <= half_fov_rad;
	}
};

void scoreRecall(const std::vector<dynamic::TTrackRow>& rows, const TCueTruth& t, const TCameraView& view,
				 TCueScore& sc)
{
	std::vector<std::vector<const dynamic::TTrackRow*>> persons(t.poses.size());
	for (const auto& r : rows)
		if (r.scan < t.poses.size() && std::string(r.kind) == "person" &&
			r.track.state == dynamic::ETrackState::dynamic)
			persons[r.scan].push_back(&r);
	std::map<int, std::pair<size_t, size_t>> firstSeenCovered;  // person -> (first visible, first covered) scan
	for (size_t s = 0; s < t.poses.size(); ++s)
		for (const auto& [id, beams] : t.beams[s])
		{
			if (beams < kMinBeams || !t.people[s].count(id)) continue;
			const auto p = inRobotFrame(t, s, t.people[s].at(id));
			bool covered = false;
			for (const auto* r : persons[s]) covered = covered || std::hypot(r->x_robot_m - p.x, r->y_robot_m - p.y) <= kMatch_m;
			const bool inView = view.contains(p);
			sc.visible++, sc.visible_in_view += inView, sc.covered += covered, sc.covered_in_view += covered && inView;
			auto& fc = firstSeenCovered.try_emplace(id, s, SIZE_MAX).first->second;
			if (covered) fc.second = std::min(fc.second, s);
		}
	double sum = 0;
	size_t n = 0;
	for (const auto& [id, fc] : firstSeenCovered)
		if (fc.second != SIZE_MAX) sum += static_cast<double>(fc.second - fc.first) * t.scan_period_s, ++n;
	sc.first_delay_s = n ? sum / static_cast<double>(n) : NAN;
}

TCameraView cameraView(const std::vector<io::TRawlogEntry>& entries)
{
	for (const auto& e : entries)
		if (auto img = std::dynamic_pointer_cast<mrpt::obs::CObservationImage>(e.observation))
		{
			const auto cam = vision::mountedCameraOf(*img, vision::cameraFromOptions({}));
			return {cam.sensorPose.x(), cam.sensorPose.y(), std::atan(0.5 * cam.intrinsics.ncols / cam.intrinsics.fx())};
		}
	throw std::runtime_error("the sample has no CObservationImage");
}

/** Cue regions of the vision rows whose bearing range, widened by the
 * filter's camera_cue_margin_deg, holds a true person (nearest scan in time). */
size_t cuesOnPeople(const std::vector<slam::TVisionRow>& rows, const TCueTruth& t, const TCameraView& view,
					double margin_rad)
{
	size_t n = 0;
	for (const auto& row : rows)
	{
		const size_t s = static_cast<size_t>(std::lower_bound(t.t_s.begin(), t.t_s.end(), row.t_s - 0.5 * t.scan_period_s) -
											 t.t_s.begin());
		if (s >= t.poses.size()) continue;
		for (const auto& r : row.regions)
		{
			bool hit = false;
			for (const auto& [id, w] : t.people[s])
			{
				const auto p = inRobotFrame(t, s, w);
				const double b = std::atan2(p.y - view.y_m, p.x - view.x_m);
				hit = hit || (b >= r.bearing_min_rad - margin_rad && b <= r.bearing_max_rad + margin_rad);
			}
			n += hit;
		}
	}
	return n;
}

TCueScore runAndScore(const std::string& dir, const std::vector<io::TRawlogEntry>& entries, const TCueTruth& truth,
					  bool cueOn, double& seconds)
{
	const std::vector<std::string> overrides{
		"vision.noise_floor_px=0.1", "vision.corner_min_distance_px=5", "vision.cue_cluster_distance_px=20",
		std::string("dynamic_objects.camera_cue_evidence=") + (cueOn ? "true" : "false")};
	slam::CMappingPipeline pipeline(common::loadConfigWithOverrides("config_ini/hslam-default.ini", overrides));
	TCueScore sc;
	pipeline.addScanObserver([&](const mrpt::obs::CObservation2DRangeScan&, const mrpt::poses::CPose2D&) {
		if (!pipeline.dynamicFilter()) return;
		for (const auto& leg : pipeline.dynamicFilter()->lastFrame().legs) sc.cue_legs += leg.camera_cue;
	});
	const auto t0 = std::chrono::steady_clock::now();
	for (const auto& e : entries) pipeline.processEntry(e);
	pipeline.finish();
	seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	if (pipeline.counters().laser_scans != truth.poses.size())
		throw std::runtime_error(dir + ": " + std::to_string(pipeline.counters().laser_scans) + " scans mapped, " +
								 std::to_string(truth.poses.size()) + " true poses");
	for (const auto& row : pipeline.visionStage().rows()) sc.cues += row.regions.size();
	const TCameraView view = cameraView(entries);
	sc.cues_on_people = cuesOnPeople(pipeline.visionStage().rows(), truth, view,
									 pipeline.dynamicFilter() ? pipeline.dynamicFilter()->options().camera_cues.margin_rad : 0.0);
	scoreRecall(pipeline.trackRows(), truth, view, sc);
	scoreFalseTracks(pipeline.trackRows(), truth, sc);
	return sc;
}

/** The table of the off / on runs (recall in %, delays and run time in s). */
CReportTable cueTable()
{
	return CReportTable(std::cout, {{"camera cues", 18, true},
									{"recall", 8},
									{"in view", 12},
									{"first (s)", 12},
									{"false P", 9},
									{"false L", 10},
									{"cues", 7},
									{"cue legs", 10},
									{"run s", 8}});
}

void printCueRow(const CReportTable& table, const std::string& name, const TCueScore& s, double seconds)
{
	const auto pct = [](size_t a, size_t b) { return b ? 100.0 * static_cast<double>(a) / static_cast<double>(b) : NAN; };
	const auto share = [](size_t a, size_t b) { return std::to_string(a) + "/" + std::to_string(b); };
	table.printRow({name, fixed(pct(s.covered, s.visible), 1), fixed(pct(s.covered_in_view, s.visible_in_view), 1),
					fixed(s.first_delay_s, 2), share(s.false_person_tracks, s.person_tracks),
					share(s.false_leg_tracks, s.leg_tracks), std::to_string(s.cues), std::to_string(s.cue_legs),
					fixed(seconds, 2)});
}
}  // namespace

bool runVisionCuesPart(const std::string& dir)
{
	if (!std::filesystem::exists(dir + "/sim.rawlog"))
	{
		std::cerr << "hslam-bench vision: " << dir << "/sim.rawlog not found (the cue part needs rawlog_samples/camera)\n";
		return false;
	}
	const std::vector<io::TRawlogEntry> entries = io::readRawlogEntries(dir + "/sim.rawlog");
	const TCueTruth truth = loadCueTruth(dir);
	std::cout << "Camera cues vs laser leg tracks (" << dir << ", batch pipeline, " << truth.poses.size()
			  << " scans; recall of visible person-scans, %)\n";
	const CReportTable table = cueTable();
	table.printHeader();
	double secOff = 0, secOn = 0;
	const TCueScore off = runAndScore(dir, entries, truth, false, secOff), on = runAndScore(dir, entries, truth, true, secOn);
	printCueRow(table, "off (default)", off, secOff);
	printCueRow(table, "on", on, secOn);
	std::cout << "cue regions whose bearing range (+- camera_cue_margin_deg) holds a true person: " << off.cues_on_people
			  << " of " << off.cues << "\n";
	const auto frac = [](size_t a, size_t b) { return b ? static_cast<double>(a) / static_cast<double>(b) : NAN; };
	CKeyValueLines(std::cout, 4)("cue_recall_off", frac(off.covered, off.visible))(
		"cue_recall_on", frac(on.covered, on.visible))("cue_regions_on_people", frac(off.cues_on_people, off.cues))(
		"cue_false_person_tracks_off", off.false_person_tracks)("cue_false_person_tracks_on", on.false_person_tracks)(
		"cue_first_confirmation_s_off", off.first_delay_s)("cue_first_confirmation_s_on", on.first_delay_s);
	return true;
}

}  // namespace hslam::bench
