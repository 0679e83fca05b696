/* hslam-bench sonar-batch: the sonar stage of the batch job (CMappingPipeline
 * with CSonarMappingStage) on the simulated samples (rawlog_samples/<name>/:
 * sim.rawlog, ground_truth.tum, gt_map.gridmap.gz, corners.csv), default
 * pose estimation, against ground truth:
 *   - map agreement with the ground-truth map (5 cm, resampled onto our
 *     0.1 m cells by benchdata::resampleOntoOurCells: a cell is occupied if any
 *     wall passes through it) for the laser-only map and the laser+sonar maps
 *     (fast model with weights 0.1 / 0.05 / 0.02, standard model 0.1) and
 *     the sonar-only map, all over the same cells (the union of the observed
 *     areas), with
 *       agreement      = same class / cells known in either map,
 *       agree(known)   = same class / cells known in ours,
 *       false occ      = occupied in ours, not in the truth,
 *       walls found    = truth-occupied cells that ours marks occupied;
 *   - TBF corners (support >= 1 and >= [tbf] min_support) against the true
 *     point features within 0.2 m and 0.3 m: the wall corners (corners.csv)
 *     and the static circles of the scene (pillars, chair and table legs;
 *     distance to their surface), which echo like edges;
 *   - the time of the sonar stages per ring observation.
 * The map frame is placed on the truth with the first true pose. */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/common/config_overrides.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/eval/point_landmark_score.h>
#include <hslam/io/rawlog_scans.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/sim/scene.h>
#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

namespace hslam::bench
{
namespace
{
struct TConfigRun
{
	std::string name;
	std::vector<std::string> overrides;
};

const std::vector<TConfigRun> kRuns = {
	{"laser only", {"sonar_model.enabled=false"}},
	{"laser+sonar fast w=0.1", {"sonar_model.enabled=true", "sonar_model.weight=0.1"}},
	{"laser+sonar fast w=0.05", {"sonar_model.enabled=true", "sonar_model.weight=0.05"}},
	{"laser+sonar fast w=0.02", {"sonar_model.enabled=true", "sonar_model.weight=0.02"}},
	{"laser+sonar std w=0.1", {"sonar_model.enabled=true", "sonar_model.weight=0.1", "sonar_model.model=standard"}},
};

struct TRunResult
{
	std::string name;
	std::unique_ptr<slam::CMappingPipeline> pipeline;
	double seconds = 0;
};

double stageMean(const common::CStageTimer& timer, const std::string& stage, double* total = nullptr)
{
	for (const auto& s : timer.stats())
		if (s.stage == stage)
		{
			if (total) *total = s.total_ms;
			return s.mean_ms;
		}
	if (total) *total = 0;
	return 0;
}

struct TTotals
{
	size_t laserAgreed = 0, laserCompared = 0, fusedAgreed = 0, fusedCompared = 0, laserKnown = 0, fusedKnown = 0;
	size_t cornersFound = 0, cornersNear = 0;
};

/** Static circles of the sample's scene (config_ini/sim-<sample>.ini [world] scene_file). */
std::vector<sim::TCircle> staticCircles(const std::string& sample)
{
	const std::string ini = "config_ini/sim-" + sample + ".ini";
	const auto cfg = common::loadIniFile(ini);
	const std::string scene = cfg.read_string("world", "scene_file", "");
	if (scene.empty()) return {};
	return sim::loadSceneFile("config_ini/" + scene).world.circles();
}

CReportTable mapTable()
{
	return CReportTable(std::cout, {{"sample", 10, true},
									{"map", 26, true},
									{"agreement", 10},
									{"agree(known)", 13},
									{"known", 8},
									{"false occ", 10},
									{"walls", 8},
									{"ms/ring", 10}});
}

void printRow(const std::string& sample, const std::string& name, const benchdata::TMapScore& a, double msPerRing)
{
	mapTable().printRow({sample, name, fixed(a.agreement(), 4), fixed(a.agreementOfOursKnown(), 4),
						 std::to_string(a.ours_known), std::to_string(a.false_occupied), fixed(a.wallsFound(), 3),
						 fixed(msPerRing, 4)});
}

/** Rows of the TBF table (its header is printed with the rows at the end). */
CReportTable tbfTable(std::ostream& out)
{
	return CReportTable(out, {{"sample", 10, true},
							  {"support", 8},
							  {"corners", 9},
							  {"walls", 7},
							  {"circles", 9},
							  {"prec@0.2", 10},
							  {"prec@0.3", 10},
							  {"wall rec", 11},
							  {"circle rec", 11},
							  {"   (rec@0.3 m)", 0}});
}

CReportTable costTable(std::ostream& out)
{
	return CReportTable(out, {{"sample", 10, true},
							  {"laser-only s", 12},
							  {"fused s", 12},
							  {"rings", 8},
							  {"update ms", 11},
							  {"tbf ms/ring", 11},
							  {"sonar %", 10},
							  {"sensor maps %", 10}});
}

/** Every run of kRuns on one sample's rawlog; `cells` gets the union of their observed areas. */
std::vector<TRunResult> runConfigs(const std::string& ini, const std::string& dir, maps::TCellBounds& cells)
{
	const std::vector<io::TRawlogEntry> entries = io::readRawlogEntries(dir + "/sim.rawlog");
	std::vector<TRunResult> runs;
	for (const auto& config : kRuns)
	{
		auto overrides = config.overrides;
		overrides.push_back("tbf.min_support=1");
		TRunResult r;
		r.name = config.name;
		r.pipeline = std::make_unique<slam::CMappingPipeline>(common::loadConfigWithOverrides(ini, overrides));
		if (&config == &kRuns[1]) r.pipeline->keepSensorMaps();
		const auto t0 = std::chrono::steady_clock::now();
		for (const auto& e : entries) r.pipeline->processEntry(e);
		r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		cells.include(r.pipeline->grid().observedBounds());
		runs.push_back(std::move(r));
	}
	return runs;
}

/** One table row per map of the sample against the truth; the laser-only and fused runs count into `totals`. */
void printMapRows(const std::string& sample, const std::vector<TRunResult>& runs,
				  const mrpt::maps::COccupancyGridMap2D& truthGrid, TTotals& totals)
{
	for (const auto& r : runs)
	{
		const auto a = benchdata::scoreMap(r.pipeline->grid(), truthGrid);
		printRow(sample, r.name, a, stageMean(r.pipeline->timer(), "sonar_update"));
		if (&r == &runs[0])
			totals.laserAgreed += a.agreed, totals.laserCompared += a.compared, totals.laserKnown += a.ours_known;
		if (&r == &runs[1])
			totals.fusedAgreed += a.agreed, totals.fusedCompared += a.compared, totals.fusedKnown += a.ours_known;
	}
	printRow(sample, "sonar only (fast, w=1)", benchdata::scoreMap(*runs[1].pipeline->sonarOnlyMap(), truthGrid),
			 0.0);
}

/** TBF corners of the fused run against the true point features: the wall
 * corners (corners.csv) and the static circles of the scene (pillars, chair
 * and table legs), which reflect sonar like edges and are what TBF finds
 * most in these worlds. Rows go to `table`. */
void scoreTbfCorners(const std::string& sample, const std::string& dir, const slam::CMappingPipeline& fused,
					 const mrpt::poses::CPose2D& oursInTruth, std::ostream& table, TTotals& totals)
{
	const auto wallCorners = eval::readPointsCsv(dir + "/corners.csv");
	std::vector<mrpt::math::TPoint2D> circles;
	std::vector<double> circleRadii;
	for (const auto& c : staticCircles(sample)) circles.push_back(c.centre), circleRadii.push_back(c.radius_m);
	auto allPoints = wallCorners;
	allPoints.insert(allPoints.end(), circles.begin(), circles.end());
	std::vector<double> allRadii(wallCorners.size(), 0.0);
	allRadii.insert(allRadii.end(), circleRadii.begin(), circleRadii.end());
	const int minSupport = slam::TTbfStageOptions().min_support;
	for (const int support : {1, minSupport})
	{
		std::vector<mrpt::math::TPoint2D> found;
		for (const auto& c : fused.sonarStage().corners())
			if (c.support >= support) found.push_back(c.point);
		const auto s2 = eval::scorePointLandmarks(found, allPoints, 0.2, oursInTruth, allRadii);
		const auto s3 = eval::scorePointLandmarks(found, allPoints, 0.3, oursInTruth, allRadii);
		const auto w3 = eval::scorePointLandmarks(found, wallCorners, 0.3, oursInTruth);
		const auto c3 = eval::scorePointLandmarks(found, circles, 0.3, oursInTruth, circleRadii);
		tbfTable(table).printRow({sample, std::to_string(support), std::to_string(found.size()),
								  std::to_string(wallCorners.size()), std::to_string(circles.size()),
								  fixed(s2.precision(), 3), fixed(s3.precision(), 3), fixed(w3.recall(), 3),
								  fixed(c3.recall(), 3), ""});
		if (support == minSupport) totals.cornersFound += s3.found, totals.cornersNear += s3.found_near_truth;
	}
}

/** The cost row of the sample: the sensor maps repeat the laser grid update
 * and the sonar update on their own grids (untimed), so their cost is about
 * the timed totals. */
void printCostRow(const std::string& sample, const std::vector<TRunResult>& runs, std::ostream& table)
{
	const auto& fused = *runs[1].pipeline;
	double gridTotal = 0, sonarTotal = 0, tbfTotal = 0;
	stageMean(fused.timer(), "grid_update", &gridTotal);
	const double sonarMean = stageMean(fused.timer(), "sonar_update", &sonarTotal);
	const double tbfMean = stageMean(fused.timer(), "sonar_corners", &tbfTotal);
	const double jobMs = 1e3 * runs[1].seconds;
	costTable(table).printRow({sample, fixed(runs[0].seconds, 2), fixed(runs[1].seconds, 2),
							   std::to_string(fused.counters().sonar_observations), fixed(sonarMean, 4),
							   fixed(tbfMean, 4), fixed(100.0 * (sonarTotal + tbfTotal) / jobMs, 1),
							   fixed(100.0 * (gridTotal + sonarTotal) / jobMs, 1)});
}

void printTotals(const TTotals& totals)
{
	std::cout << "\n";
	CKeyValueLines(std::cout, 4)("sonar_batch_laser_only_agreement",
								 static_cast<double>(totals.laserAgreed) / totals.laserCompared)(
		"sonar_batch_fused_agreement", static_cast<double>(totals.fusedAgreed) / totals.fusedCompared)(
		"sonar_batch_laser_only_known_agreement", static_cast<double>(totals.laserAgreed) / totals.laserKnown)(
		"sonar_batch_fused_known_agreement", static_cast<double>(totals.fusedAgreed) / totals.fusedKnown)(
		"sonar_batch_tbf_precision_0_3m",
		totals.cornersFound ? static_cast<double>(totals.cornersNear) / totals.cornersFound : 0.0);
}
}  // namespace

int runSonarBatchSuite(const std::string& dataDir)
{
	const std::string ini = "config_ini/hslam-default.ini";
	if (!std::filesystem::exists(ini)) throw std::runtime_error(ini + ": run hslam-bench from the repository root");
	std::cout << "Sonar in the batch job (CMappingPipeline, default pose estimation) vs ground truth, 0.1 m cells\n";
	mapTable().printHeader();
	TTotals totals;
	std::ostringstream tbfRows, costRows;
	for (const std::string sample : {"lab", "corridor", "umbmark", "floor"})
	{
		const std::string dir = dataDir + "/" + sample;
		maps::TCellBounds cells;
		const std::vector<TRunResult> runs = runConfigs(ini, dir, cells);
		printMapRows(sample, runs, truthMapOnOurCells(dir, *runs[0].pipeline, cells), totals);
		scoreTbfCorners(sample, dir, *runs[1].pipeline, ourMapFrameInTruth(dir, *runs[0].pipeline), tbfRows, totals);
		printCostRow(sample, runs, costRows);
	}
	std::cout << "   agreement over the union of the observed areas of all maps; walls = truth-occupied cells found\n"
			  << "\nTBF corners vs true point features: wall corners (corners.csv) + static circles (scene)\n";
	// Headers as first published (docs/tiledmap.md), wider than some columns.
	std::cout << "sample    support  corners  walls  circles  prec@0.2  prec@0.3  wall rec  circle rec   (rec@0.3 m)\n"
			  << tbfRows.str() << "\nCost in the job (laser+sonar fast w=0.1 run, with the sensor maps kept)\n"
			  << "sample     laser-only s  fused s   rings  update ms  tbf ms/ring  sonar %  sensor maps %\n"
			  << costRows.str();
	printTotals(totals);
	return 0;
}

}  // namespace hslam::bench
