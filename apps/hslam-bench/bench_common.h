/* hslam-bench: helpers shared by the benchmark suites. */
#pragma once

#include <hslam/maps/CLaserGridInserter.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <hslam/dynamic/CDynamicObjectFilter.h>
#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <chrono>
#include <string>
#include <vector>

namespace hslam::bench
{
/** A laser scan with the robot pose it was taken at. */
struct TPosedScan
{
	mrpt::poses::CPose2D pose;
	mrpt::obs::CObservation2DRangeScan scan;
};

/** A short name for a rawlog in tables and keys: the folder for
 * <dir>/sim.rawlog (simulated samples), else the file stem; characters other
 * than letters, digits and '-' become '_'. */
std::string rawlogName(const std::string& path);

/** Reads every 2D scan of a rawlog with its dead-reckoning pose. */
std::vector<TPosedScan> loadPosedScans(const std::string& rawlogPath);

/** Wall time of fn() in seconds, the best of `repetitions` runs (the
 * minimum is the most repeatable figure on a shared machine). */
template <class F>
double bestTimeOf(int repetitions, F&& fn)
{
	double best = 1e300;
	for (int r = 0; r < repetitions; ++r)
	{
		const auto t0 = std::chrono::steady_clock::now();
		fn();
		const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - t0;
		best = std::min(best, dt.count());
	}
	return best;
}

/** The MRPT sample rawlog shipped with mrpt-common (real laser + odometry). */
inline const char* kMrptSampleRawlog = "/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";

/* Laser insertion with comparable settings for our tiled grid and MRPT's
 * COccupancyGridMap2D (used by the grid and sonar suites):
 *   - range limit 3 m on both (MRPT maxDistanceInsertion; ours max_range_m
 *     with insert_free_beyond_range, which is what MRPT does with long beams),
 *   - invalid beams ignored on both (MRPT considerInvalidRangesAsFreeSpace off),
 *   - MRPT's update certainties set to our sensor probabilities (0.9 / 0.7),
 *   - the MRPT grid pre-sized to the final area (no resizing during the run). */
constexpr double kRangeLimit_m = 3.0;
maps::CLaserGridInserter::TOptions ourLaserOptions();
void insertOurs(maps::CTiledOccupancyGrid& grid, const std::vector<TPosedScan>& scans);
/** An MRPT grid covering the observed cells of `sizedLike` (+5 cells). */
mrpt::maps::COccupancyGridMap2D makeMrptGrid(const maps::CTiledOccupancyGrid& sizedLike);
void insertMrpt(mrpt::maps::COccupancyGridMap2D& grid, const std::vector<TPosedScan>& scans);
/** Bytes of an MRPT grid's cells. */
size_t mrptGridBytes(const mrpt::maps::COccupancyGridMap2D& grid);

int runGridSuite(const std::vector<std::string>& rawlogs, int repetitions);
/** Sonar models, TBF and laser tiled-vs-MRPT on simulated runs; images into `outDir`. */
int runSonarSuite(int repetitions, const std::string& outDir);
/** The sonar stage of the batch job on the simulated samples under dataDir
 * (bench_sonar_batch.cpp): map agreement with and without sonar, TBF corners. */
int runSonarBatchSuite(const std::string& dataDir);

/** Line extractors on thesis table 3 scenes and real scans (bench_lines.cpp);
 * `logs` empty: ../shared/datasets/carmen/{intel,aces,csail}-corrected.log.gz
 * (relative to the worktree root, build/ or build/bin/). */
int runLinesSuite(const std::vector<std::string>& logs, int repetitions);

/** Leg detection / tracking / exclusion on a folder laid out like
 * ../shared/datasets/legs (bench_legs.cpp); images go to outDir. */
int runLegsSuite(const std::string& dataDir, const std::string& outDir, const std::string& configFile);


/** An MRPT grid map file (.gridmap.gz, e.g. a simulator's gt_map). */
mrpt::maps::COccupancyGridMap2D loadGridmap(const std::string& path);
/** Our map frame in the simulated truth's frame (placed by the first true pose). */
mrpt::poses::CPose2D ourMapFrameInTruth(const std::string& sampleDir, const slam::CMappingPipeline& pipeline);
/** The ground-truth map of a simulated sample folder (gt_map.gridmap.gz,
 * ground_truth.tum) resampled onto `cells` of the pipeline's grid, the map
 * frame placed on the truth with the first true pose. */
mrpt::maps::COccupancyGridMap2D truthMapOnOurCells(const std::string& sampleDir, const slam::CMappingPipeline& pipeline,
												   const maps::TCellBounds& cells);
/** Map quality against a reference for several grid ranges ([laser_model]
 * max_range_m; bench_grid_range.cpp). */
int runGridRangeSuite(const std::string& samplesDir, const std::vector<std::string>& rawlogs,
					  const std::vector<std::string>& references);

/** The dynamic object filter on simulated samples with walking people and
 * per-beam ground truth (bench_legs_sim.cpp): every folder under dataDir
 * holding sim.rawlog, ground_truth.tum, people.csv.gz, beam_labels.csv.gz. */
int runLegsSimSuite(const std::string& dataDir, const std::string& outDir, const std::string& configFile);

/** The default pipeline (hslam-process) against MRPT's icp-slam, CPU ms per
 * scan and ATE (bench_pipeline.cpp); parses its own options from argv. */
int runPipelineSuite(int argc, char** argv);

/** Pose-graph optimisation against graph size (synthetic laps up to 10 000
 * keyframes) and the loop-closure back-end's cost in hslam-process
 * (bench_graph.cpp); parses its own options from argv. */
int runGraphSuite(int argc, char** argv);

/** Our subsumption controller vs MRPT's reactive navigator (ND, VFF,
 * FullEval) on the simulated nav scenarios (bench_nav.cpp); own options. */
int runNavSuite(int argc, char** argv);

/** ARCOS parser, driver and recorders against the emulators (bench_hwdrivers.cpp). */
int runHwdriversSuite(int repetitions);

/** Writes the two maps side by side in one frame (left "without exclusion",
 * right "with exclusion") to pngPath; throws naming the file if it cannot. */
void saveExclusionComparison(const maps::CTiledOccupancyGrid& without, const maps::CTiledOccupancyGrid& with,
							 int pixelsPerCell, const std::string& pngPath);

}  // namespace hslam::bench
