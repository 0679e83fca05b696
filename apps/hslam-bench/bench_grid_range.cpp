/* hslam-bench grid-range: which [laser_model] max_range_m (the range inserted
 * into the grid; the thesis uses 3 m) gives the best map (issue 12, item 4).
 * For each range the default batch pipeline runs (estimated poses), and its
 * grid is compared cell by cell with a reference map over the union of the
 * observed cells:
 *   - simulated samples (<samples>/{lab,corridor,floor}): the simulator's
 *     true map (gt_map.gridmap.gz), resampled onto our cells;
 *   - real logs (-r RAWLOG -g REFERENCE.tum): the same scans inserted with
 *     the same inserter and range at the reference poses (associated by time
 *     stamp, placed in our map frame by the first scan's pose).
 * Printed per input and range: agreement (same class / cells known in either
 * map), agree(known) (same class / cells ours knows), the number of cells
 * ours knows correctly (coverage that is right) and wrongly, and walls found
 * (reference-occupied cells ours marks occupied). */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/common/config_overrides.h>
#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/benchdata/map_scoring.h>
#include <hslam/maps/grid_rendering.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>

namespace hslam::bench
{
namespace
{
const std::vector<double> kRanges_m = {3, 4, 5, 6, 8, 12};
const char* kIni = "config_ini/hslam-default.ini";

/** One pipeline run at a range, with the scans and the poses it inserted them at. */
struct TRangeRun
{
	std::unique_ptr<slam::CMappingPipeline> pipeline;
	std::vector<TPosedScan> scans;
};

TRangeRun runAtRange(const std::string& rawlog, double range_m)
{
	TRangeRun run;
	const auto cfg = common::loadConfigWithOverrides(kIni, {"laser_model.max_range_m=" + std::to_string(range_m)});
	run.pipeline = std::make_unique<slam::CMappingPipeline>(cfg);
	run.pipeline->addScanObserver([&run](const mrpt::obs::CObservation2DRangeScan& scan,
										 const mrpt::poses::CPose2D& pose) { run.scans.push_back({pose, scan}); });
	io::CRawlogReader reader(rawlog);
	for (io::TRawlogEntry e; reader.next(e);) run.pipeline->processEntry(e);
	if (run.scans.empty()) throw std::runtime_error(rawlog + ": no laser scans");
	return run;
}

/** The run's scans inserted at the reference poses (same inserter, same range). */
maps::CTiledOccupancyGrid referenceGrid(const TRangeRun& run, const common::TTrajectory2D& reference, double range_m)
{
	std::map<long long, mrpt::poses::CPose2D> byStamp;  // millisecond stamps
	for (const auto& p : reference)
		byStamp[std::llround(p.t_s * 1000)] = mrpt::poses::CPose2D(p.pose.x, p.pose.y, p.pose.phi);
	const auto cfg = common::loadConfigWithOverrides(kIni, {"laser_model.max_range_m=" + std::to_string(range_m)});
	maps::CTiledOccupancyGrid grid(common::loadedOptions<maps::CTiledOccupancyGrid::TOptions>(cfg, "grid"));
	maps::CLaserGridInserter inserter(common::loadedOptions<maps::CLaserGridInserter::TOptions>(cfg, "laser_model"));
	std::optional<mrpt::poses::CPose2D> firstInOurs;  // the reference frame -> our map frame
	for (const auto& s : run.scans)
	{
		const auto it = byStamp.find(std::llround(mrpt::Clock::toDouble(s.scan.timestamp) * 1000));
		if (it == byStamp.end()) continue;
		if (!firstInOurs) firstInOurs = s.pose + (-it->second);
		inserter.insert(grid, *firstInOurs + it->second, s.scan);
	}
	if (!firstInOurs) throw std::runtime_error("reference trajectory: no pose at any scan's time stamp");
	return grid;
}

CReportTable rangeTable()
{
	return CReportTable(std::cout, {{"input", 14, true},
									{"range m", 8},
									{"agreement", 11},
									{"agree(known)", 14},
									{"right", 10},
									{"wrong", 10},
									{"walls", 8}});
}

void printRow(const CReportTable& table, const std::string& input, double range_m, const benchdata::TMapScore& a)
{
	table.printRow({input, fixed(range_m, 0), fixed(a.agreement(), 4), fixed(a.agreementOfOursKnown(), 4),
					std::to_string(a.agreed), std::to_string(a.ours_known - a.agreed), fixed(a.wallsFound(), 3)});
}
}  // namespace

int runGridRangeSuite(const std::string& samplesDir, const std::vector<std::string>& rawlogs,
					  const std::vector<std::string>& references)
{
	if (rawlogs.size() != references.size())
		throw std::runtime_error("grid-range: give one -g REFERENCE.tum per -r RAWLOG");
	std::cout << "Grid range ([laser_model] max_range_m) against reference maps, default pipeline, 0.1 m cells\n";
	const CReportTable table = rangeTable();
	table.printHeader();
	for (const std::string sample : {"lab", "corridor", "floor"})
		for (const double r : kRanges_m)
		{
			const std::string dir = samplesDir + "/" + sample;
			const TRangeRun run = runAtRange(dir + "/sim.rawlog", r);
			const auto cells = run.pipeline->grid().observedBounds();
			printRow(table, sample, r, benchdata::scoreMap(run.pipeline->grid(), truthMapOnOurCells(dir, *run.pipeline, cells)));
		}
	for (size_t i = 0; i < rawlogs.size(); ++i)
		for (const double r : kRanges_m)
		{
			const TRangeRun run = runAtRange(rawlogs[i], r);
			const auto reference = referenceGrid(run, common::readTumFile(references[i]), r);
			auto cells = run.pipeline->grid().observedBounds();
			cells.include(reference.observedBounds());
			const std::string name = rawlogs[i].substr(rawlogs[i].find_last_of('/') + 1);
			printRow(table, name.substr(0, 13), r,
					 benchdata::scoreMap(run.pipeline->grid(), maps::toMrptGrid(reference, cells)));
		}
	return 0;
}

}  // namespace hslam::bench
