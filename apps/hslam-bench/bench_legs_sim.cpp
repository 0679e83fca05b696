/* hslam-bench legs-sim: the dynamic object filter (libs/dynamic, thesis
 * defaults) on simulated samples with walking people, where the truth is
 * known (rawlog_samples/<name>/ from hslam-simulate):
 *   - per-beam precision / recall of "hits a confirmed dynamic object"
 *     against beam_labels.csv.gz (kind = person_leg);
 *   - identity switches per person: the dynamic person track nearest each
 *     true person (people.csv.gz, within 0.5 m) changing id, over the scans
 *     where the person is hit by >= 3 beams within the detector's range
 *     (coverage = share of those scans with a dynamic track on the person);
 *     also counted: switches after a gap no longer than the tracker's memory
 *     (those re-identification is meant to avoid);
 *   - map cells wrongly occupied by people, with / without exclusion: grid
 *     cells hit only by person beams (never by a static-structure beam) that
 *     end occupied.
 * Robot poses: the ground truth (ground_truth.tum, one pose per scan), so the
 * numbers measure the filter, not odometry drift. */
#include "bench_common.h"
#include "bench_csv.h"
#include "bench_report.h"

#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/dynamic/dynamic_profiles.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/io/CGzLineReader.h>
#include <hslam/io/rawlog_scans.h>
#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/maps/grid_rendering.h>
#include <hslam/slam/CDynamicMappingStage.h>
#include <mrpt/system/datetime.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace hslam::bench
{
namespace
{
namespace fs = std::filesystem;

struct TSimResult
{
	size_t scans = 0, tp = 0, fp = 0, fn = 0;
	size_t people = 0, person_frames = 0, covered_frames = 0, id_switches = 0, id_switches_short = 0;
	size_t people_cells_without = 0, people_cells_with = 0;
	double filter_s = 0;
};

/** Per-scan ground truth of a simulated sample: the beams on people's legs
 * (beam_labels.csv.gz) and the people's positions (people.csv.gz). */
struct TSimLabels
{
	std::vector<std::set<size_t>> person_beams;  //!< per scan: beams on a person's leg
	std::vector<std::map<int, size_t>> beams_of_person;  //!< per scan: person id -> beams on it
	std::vector<std::vector<std::pair<int, mrpt::math::TPoint2D>>> people;  //!< per scan: (id, position)
	std::set<int> person_ids;
};

TSimLabels readSimLabels(const fs::path& dir, size_t scanCount)
{
	const std::string labelsFile = (dir / "beam_labels.csv.gz").string(), peopleFile = (dir / "people.csv.gz").string();
	TSimLabels l;
	l.person_beams.resize(scanCount), l.beams_of_person.resize(scanCount), l.people.resize(scanCount);
	for (const auto& row : readCsv(labelsFile))
		if (row.at("kind") == "person_leg")
		{
			const size_t scan = static_cast<size_t>(number(row, "scan", labelsFile));
			if (scan >= scanCount) continue;
			l.person_beams[scan].insert(static_cast<size_t>(number(row, "beam", labelsFile)));
			l.beams_of_person[scan][static_cast<int>(number(row, "object", labelsFile))]++;
		}
	for (const auto& row : readCsv(peopleFile))
	{
		const size_t scan = static_cast<size_t>(number(row, "scan", peopleFile));
		const int id = static_cast<int>(number(row, "person", peopleFile));
		l.person_ids.insert(id);
		if (scan < scanCount)
			l.people[scan].push_back({id, {number(row, "x_m", peopleFile), number(row, "y_m", peopleFile)}});
	}
	return l;
}

/** The cells hit by person beams and by static beams (for the people-cells figure). */
struct THitCells
{
	std::set<std::pair<int, int>> person, statics;
};

/** Beam-level scores of one scan (TP / FP / FN against the labels) and the
 * cells its beams hit, split by the truth. */
void scoreBeams(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& pose,
				const std::set<size_t>& personBeams, const dynamic::TDynamicFrame& frame, double maxRange_m,
				const maps::CTiledOccupancyGrid& grid, TSimResult& r, THitCells& cells)
{
	const mrpt::poses::CPose2D sensor = pose + mrpt::poses::CPose2D(scan.sensorPose);
	for (size_t b = 0; b < scan.getScanSize(); ++b)
	{
		const bool truthDyn = personBeams.count(b) > 0, flagged = frame.beam_is_dynamic[b];
		r.tp += truthDyn && flagged;
		r.fp += !truthDyn && flagged;
		r.fn += truthDyn && !flagged;
		const double range = scan.getScanRange(b);
		if (!scan.getScanRangeValidity(b) || range > maxRange_m) continue;
		const double a = dynamic::beamBearing(scan, b) - scan.sensorPose.yaw();
		double x, y;
		sensor.composePoint(range * std::cos(a), range * std::sin(a), x, y);
		const auto c = grid.geometry().cellOf(x, y);
		(truthDyn ? cells.person : cells.statics).insert({c.gx, c.gy});
	}
}

/** Track identity against the true people over the scans. */
class CIdentityScore
{
   public:
	/** The dynamic person track nearest each true person seen by at least 3
	 * beams within the detector's range. */
	void scan(const TSimLabels& labels, size_t i, const mrpt::poses::CPose2D& pose, double t_s,
			  const dynamic::CDynamicObjectFilter& filter, TSimResult& r)
	{
		for (const auto& [id, p] : labels.people[i])
		{
			const auto seen = labels.beams_of_person[i].find(id);
			if (seen == labels.beams_of_person[i].end() || seen->second < 3 ||
				pose.distanceTo(mrpt::poses::CPose2D(p.x, p.y, 0)) > filter.options().detector.max_range_m)
				continue;
			++r.person_frames;
			const int best = nearestDynamicTrack(filter.lastFrame(), p);
			if (best < 0) continue;
			++r.covered_frames;
			const auto last = m_lastTrackOf.find(id);
			if (last != m_lastTrackOf.end() && last->second != best)
			{
				++r.id_switches;
				// Within the tracker's memory: a switch re-identification should have avoided.
				r.id_switches_short += t_s - m_lastMatch_s[id] <= filter.options().tracker.memory_s;
			}
			m_lastTrackOf[id] = best;
			m_lastMatch_s[id] = t_s;
		}
	}

   private:
	static int nearestDynamicTrack(const dynamic::TDynamicFrame& frame, const mrpt::math::TPoint2D& p)
	{
		int best = -1;
		double bestD = 0.5;
		for (const auto& t : frame.person_tracks)
		{
			const double d = std::hypot(t.x[0] - p.x, t.x[1] - p.y);
			if (t.state == dynamic::ETrackState::dynamic && d < bestD) bestD = d, best = t.id;
		}
		return best;
	}
	std::map<int, int> m_lastTrackOf;  //!< true person -> last matched track id
	std::map<int, double> m_lastMatch_s;  //!< true person -> time of that match
};

/** Occupied cells only people ever hit: the false occupied cells (map_scoring.h)
 * against the cells static-structure beams hit, that a person beam hit. */
size_t peopleOnlyOccupiedCells(const maps::CTiledOccupancyGrid& g, const THitCells& cells)
{
	const benchdata::TCellClassOf staticHits = [&cells](const maps::TGlobalCell& c) {
		return cells.statics.count({c.gx, c.gy}) ? benchdata::ECellClass::occupied : benchdata::ECellClass::unknown;
	};
	size_t n = 0;
	for (const auto& c : benchdata::falseOccupiedCells(benchdata::cellClassesOf(g), staticHits, g.observedBounds()))
		n += cells.person.count({c.gx, c.gy});
	return n;
}

/** The laser scans of a sample with their true poses (checked to pair up). */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> readSampleScans(const fs::path& dir, common::TTrajectory2D& truth)
{
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	for (const auto& s : io::readRangeScans((dir / "sim.rawlog").string()))
		if (s->sensorLabel == "LASER") scans.push_back(s);
	truth = common::readTumFile((dir / "ground_truth.tum").string());
	if (truth.size() != scans.size())
		throw std::runtime_error((dir / "ground_truth.tum").string() + ": " + std::to_string(truth.size()) +
								 " poses for " + std::to_string(scans.size()) + " laser scans");
	return scans;
}

TSimResult runSample(const fs::path& dir, const dynamic::CDynamicObjectFilter::TOptions& options,
					 const std::string& pngPath)
{
	common::TTrajectory2D truth;
	const auto scans = readSampleScans(dir, truth);
	const TSimLabels labels = readSimLabels(dir, scans.size());
	TSimResult r;
	r.people = labels.person_ids.size();
	maps::CLaserGridInserter inserter;
	maps::CTiledOccupancyGrid without, with;
	slam::CDynamicMappingStage stage(inserter, std::make_unique<dynamic::CDynamicObjectFilter>(options));
	stage.addGrid(with);
	const dynamic::CDynamicObjectFilter& filter = *stage.filter();
	THitCells cells;
	CIdentityScore identity;
	for (size_t i = 0; i < scans.size(); ++i)
	{
		const auto& scan = *scans[i];
		const mrpt::poses::CPose2D pose(truth[i].pose);
		const auto t0 = std::chrono::steady_clock::now();
		const auto& update = stage.filterScan(scan, pose, mrpt::Clock::toDouble(scan.timestamp));
		r.filter_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		++r.scans;
		inserter.insert(without, pose, scan);
		stage.insertScan(0, scan, pose, update);  // late exclusions, then the scan with its mask
		scoreBeams(scan, pose, labels.person_beams[i], filter.lastFrame(), inserter.options().max_range_m, without, r,
				   cells);
		identity.scan(labels, i, pose, mrpt::Clock::toDouble(scan.timestamp), filter, r);
	}
	r.people_cells_without = peopleOnlyOccupiedCells(without, cells);
	r.people_cells_with = peopleOnlyOccupiedCells(with, cells);
	if (!pngPath.empty()) saveExclusionComparison(without, with, 2, pngPath);
	return r;
}

double ratio(size_t a, size_t b) { return static_cast<double>(a) / static_cast<double>(std::max<size_t>(1, b)); }

TSimResult runAllSamples(const std::vector<fs::path>& samples, const dynamic::CDynamicObjectFilter::TOptions& options,
						 const std::string& label, const std::string& pngDir)
{
	TSimResult total;
	std::cout << "Simulated samples (ground-truth poses; options: " << label << ")\n";
	const CReportTable table(std::cout, {{"", 2, true},
										 {"sample", 10, true},
										 {"scans", 6},
										 {"people", 7},
										 {"beam precision", 16},
										 {"recall", 8},
										 {"coverage", 10},
										 {"id switches", 13},
										 {"  people cells without/with", 0}});
	table.printHeader();
	for (const auto& dir : samples)
	{
		const std::string name = dir.filename().string();
		const auto r = runSample(dir, options, pngDir.empty() ? "" : pngDir + "/legs_sim_" + name + "_maps.png");
		table.printRow({"", name, std::to_string(r.scans), std::to_string(r.people), fixed(ratio(r.tp, r.tp + r.fp), 3),
						fixed(ratio(r.tp, r.tp + r.fn), 3), fixed(ratio(r.covered_frames, r.person_frames), 3),
						std::to_string(r.id_switches),
						padLeft(std::to_string(r.people_cells_without), 16) + " / " + std::to_string(r.people_cells_with)});
		total.scans += r.scans;
		total.tp += r.tp, total.fp += r.fp, total.fn += r.fn;
		total.people += r.people, total.person_frames += r.person_frames, total.covered_frames += r.covered_frames;
		total.id_switches += r.id_switches;
		total.id_switches_short += r.id_switches_short;
		total.people_cells_without += r.people_cells_without, total.people_cells_with += r.people_cells_with;
		total.filter_s += r.filter_s;
	}
	return total;
}

double reduction(const TSimResult& r)
{
	return r.people_cells_without ? 1.0 - ratio(r.people_cells_with, r.people_cells_without) : 0.0;
}

void printLegsSimKeys(const TSimResult& th, const TSimResult& total)
{
	CKeyValueLines(std::cout, 4)("sim_thesis_beam_precision", ratio(th.tp, th.tp + th.fp))(
		"sim_thesis_beam_recall", ratio(th.tp, th.tp + th.fn))("sim_thesis_people_cells_reduction", reduction(th))(
		"sim_scans", total.scans)("sim_beam_precision", ratio(total.tp, total.tp + total.fp))(
		"sim_beam_recall", ratio(total.tp, total.tp + total.fn))(
		"sim_person_coverage", ratio(total.covered_frames, total.person_frames))(
		"sim_id_switches_per_person", ratio(total.id_switches, total.people))(
		"sim_id_switches_within_memory_per_person", ratio(total.id_switches_short, total.people))(
		"sim_people_cells_without", total.people_cells_without)("sim_people_cells_with", total.people_cells_with)(
		"sim_people_cells_reduction", reduction(total))(
		"sim_filter_us_per_scan", 1e6 * total.filter_s / std::max<size_t>(1, total.scans));
}
}  // namespace

int runLegsSimSuite(const std::string& dataDir, const std::string& outDir, const std::string& configFile)
{
	// Defaults (or [dynamic_objects] of configFile), and for comparison the
	// thesis rule set (the simulated LMS200 has the thesis' 1 deg).
	const std::string thesisIni = "config_ini/hslam-legs-thesis.ini";  // run from the repository root
	const auto options = dynamic::loadDynamicOptions({configFile});
	const auto thesis = dynamic::loadDynamicOptions({thesisIni});
	std::vector<fs::path> samples;
	for (const auto& e : fs::directory_iterator(dataDir))
		if (fs::exists(e.path() / "sim.rawlog") && fs::exists(e.path() / "beam_labels.csv.gz") &&
			fs::exists(e.path() / "people.csv.gz") && fs::exists(e.path() / "ground_truth.tum"))
			samples.push_back(e.path());
	std::sort(samples.begin(), samples.end());
	if (samples.empty()) throw std::runtime_error(dataDir + ": no simulated samples (sim.rawlog + labels) found");
	fs::create_directories(outDir);

	const auto th = runAllSamples(samples, thesis, "thesis rule set, " + thesisIni, "");
	std::cout << "  people cells reduction: " << fixed(reduction(th), 3) << "\n\n";
	const auto total = runAllSamples(samples, options, configFile.empty() ? "defaults" : configFile, outDir);
	std::cout << "  maps side by side: " << outDir << "/legs_sim_<sample>_maps.png\n\n";
	printLegsSimKeys(th, total);
	return 0;
}

}  // namespace hslam::bench
