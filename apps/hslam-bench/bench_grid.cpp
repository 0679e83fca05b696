/* hslam-bench grid: our tiled grid with the thesis laser model against MRPT's
 * COccupancyGridMap2D::insertObservation on the same real scans and poses,
 * measured in the same run with comparable settings (see bench_common.h).
 * Agreement: cells classified occupied / free / unknown, compared over the
 * cells known in either map. Memory: our tiles vs MRPT's one rectangle. */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/maps/CLaserGridInserter.h>
#include <hslam/benchdata/map_scoring.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose3D.h>

#include <iomanip>
#include <iostream>

namespace hslam::bench
{
namespace
{
struct TRow
{
	std::string name;
	size_t scans = 0;
	double ours_us = 0, mrpt_us = 0, agreement = 0;
	size_t ours_bytes = 0, mrpt_bytes = 0;
};

TRow measure(const std::string& rawlog, int repetitions)
{
	const auto scans = loadPosedScans(rawlog);
	if (scans.empty()) throw std::runtime_error(rawlog + ": no 2D laser scans");
	TRow row;
	row.name = rawlog.substr(rawlog.find_last_of('/') + 1);
	row.scans = scans.size();

	maps::CTiledOccupancyGrid ours;
	insertOurs(ours, scans);
	auto mrptGrid = makeMrptGrid(ours);
	insertMrpt(mrptGrid, scans);
	row.agreement = benchdata::scoreMap(ours, mrptGrid).agreement();
	row.ours_bytes = ours.memoryBytes();
	row.mrpt_bytes = mrptGridBytes(mrptGrid);

	const double perScan = 1e6 / static_cast<double>(scans.size());
	row.ours_us = perScan * bestTimeOf(repetitions, [&] {
		maps::CTiledOccupancyGrid g;
		insertOurs(g, scans);
	});
	row.mrpt_us = perScan * bestTimeOf(repetitions, [&] {
		auto g = makeMrptGrid(ours);
		insertMrpt(g, scans);
	});
	return row;
}
}  // namespace

int runGridSuite(const std::vector<std::string>& rawlogs, int repetitions)
{
	std::vector<TRow> rows;
	for (const auto& rawlog : rawlogs) rows.push_back(measure(rawlog, repetitions));

	std::cout << "Suite grid: laser insertion, tiled grid (thesis 4.6) vs MRPT COccupancyGridMap2D, range limit "
			  << kRangeLimit_m << " m, best of " << repetitions << " runs\n\n";
	const CReportTable table(std::cout, {{"rawlog", 58, true},
										 {"scans", 7},
										 {"ours us", 12},
										 {"MRPT us", 12},
										 {"speedup", 9},
										 {"agreement", 11},
										 {"ours KiB", 11},
										 {"MRPT KiB", 11}});
	table.printHeader();
	double sumOurs = 0, sumMrpt = 0, sumAgreement = 0;
	for (const auto& r : rows)
	{
		table.printRow({r.name.substr(0, 57), std::to_string(r.scans), fixed(r.ours_us, 1), fixed(r.mrpt_us, 1),
						fixed(r.mrpt_us / r.ours_us, 2), fixed(r.agreement, 4), std::to_string(r.ours_bytes / 1024),
						std::to_string(r.mrpt_bytes / 1024)});
		sumOurs += r.ours_us * r.scans;
		sumMrpt += r.mrpt_us * r.scans;
		sumAgreement += r.agreement;
	}
	std::cout << "\n";
	CKeyValueLines(std::cout)("grid_insert_speedup_vs_mrpt", sumMrpt / sumOurs)(
		"grid_cell_agreement_vs_mrpt", sumAgreement / static_cast<double>(rows.size()));
	return 0;
}

}  // namespace hslam::bench
