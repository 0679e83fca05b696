/* hslam-bench lines: the three line extractors (thesis 4.4.2 derivative,
 * 4.4.3 IEP and RANSAC) compared as in thesis table 3.
 *
 * Synthetic part: the three environments of table 3 (line_scenes.h), each
 * seen from `kTrials` poses jittered around the origin (+-0.1 m, +-3 deg),
 * range noise 1 cm (SICK LMS) and 3 cm on the noisy wall of "corner2".
 * Ground truth = the visible part of each wall seen by >= 5 beams and
 * >= 0.2 m long; "found" / "false positive" as in line_scoring.h (5 cm,
 * 3 deg, >= 50 % overlap, one-to-one).
 * Real part (no ground-truth lines): per scan, lines found, the fraction of
 * valid points that lie on an extracted line ("covered"), the mean fit RMS,
 * and the time. CARMEN logs (*.log, *.log.gz) are converted to a temporary
 * rawlog with the foundation importer; other files are read as rawlogs.
 * Time per scan = best of `repetitions` runs over all scans, divided by the
 * scan count. MRPT's RANSAC uses MRPT's global random generator, seeded here. */
#include "bench_common.h"

#include <hslam/common/options_io.h>
#include <hslam/features/CLineExtractor.h>
#include <hslam/features/line_scenes.h>
#include <hslam/features/line_scoring.h>
#include <hslam/io/carmen_import.h>
#include <hslam/features/scan_points.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <random>

namespace hslam::bench
{
namespace
{
namespace fs = std::filesystem;
using features::CLineExtractor;
using features::TLineSegmentList;

constexpr int kTrials = 50;
constexpr double kSigma_m = 0.01, kNoisySigma_m = 0.03;

struct TSyntheticRow
{
	std::string scene, method;
	features::TLineScore total;  //!< summed over trials
	double us_per_scan = 0;
};

struct TRealRow
{
	std::string log, method;
	size_t scans = 0, lines = 0, validPoints = 0, linePoints = 0;
	double sumRms_m = 0, us_per_scan = 0;
};

void accumulate(features::TLineScore& total, const features::TLineScore& s)
{
	total.truth += s.truth;
	total.extracted += s.extracted;
	total.found += s.found;
	total.false_positives += s.false_positives;
	total.sum_endpoint_error_m += s.sum_endpoint_error_m;
	total.max_endpoint_error_m = std::max(total.max_endpoint_error_m, s.max_endpoint_error_m);
}

std::vector<std::unique_ptr<CLineExtractor>> defaultExtractors()
{
	const mrpt::config::CConfigFileMemory empty;
	std::vector<std::unique_ptr<CLineExtractor>> out;
	for (const auto& m : features::lineExtractorMethods())
		out.push_back(features::createLineExtractor(m, empty, features::lineExtractorSection(m)));
	return out;
}

std::vector<TSyntheticRow> runSynthetic(const std::vector<std::unique_ptr<CLineExtractor>>& extractors, int repetitions)
{
	std::vector<TSyntheticRow> rows;
	std::mt19937 rng(42);
	std::uniform_real_distribution<double> jitter(-1, 1);
	for (const auto& scene : features::thesisTable3Scenes(kSigma_m, kNoisySigma_m))
	{
		std::vector<features::TSyntheticScan> sims;
		for (int t = 0; t < kTrials; ++t)
		{
			const mrpt::poses::CPose2D pose(0.1 * jitter(rng), 0.1 * jitter(rng), 3.0 * M_PI / 180 * jitter(rng));
			sims.push_back(features::simulateScan(scene.walls, pose, {}, static_cast<uint32_t>(1000 + t)));
		}
		for (const auto& ex : extractors)
		{
			TSyntheticRow row{scene.name, ex->name(), {}, 0};
			mrpt::random::getRandomGenerator().randomize(1234);
			for (const auto& sim : sims)
				accumulate(row.total, features::scoreLines(features::visibleWalls(sim, 5, 0.2), ex->extract(sim.scan)));
			size_t sink = 0;
			const double t_s = bestTimeOf(repetitions, [&] {
				for (const auto& sim : sims) sink += ex->extract(sim.scan).size();
			});
			row.us_per_scan = 1e6 * t_s / static_cast<double>(sims.size()) + 0 * static_cast<double>(sink);
			rows.push_back(row);
		}
	}
	return rows;
}

bool isCarmenLog(const std::string& path)
{
	const std::string name = fs::path(path).filename().string();
	auto endsWith = [&](const std::string& s) { return name.size() >= s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0; };
	return endsWith(".log") || endsWith(".log.gz");
}

/** Front laser scans of a rawlog or CARMEN log. */
std::vector<mrpt::obs::CObservation2DRangeScan> loadScans(const std::string& path)
{
	std::string rawlog = path;
	fs::path tmpDir;
	if (isCarmenLog(path))
	{
		tmpDir = fs::temp_directory_path() / ("hslam-bench-lines-" + std::to_string(std::random_device{}()));
		fs::create_directories(tmpDir);
		rawlog = (tmpDir / "scans.rawlog").string();
		io::convertCarmenLog(path, rawlog, (tmpDir / "ref.tum").string(), {});
	}
	std::vector<mrpt::obs::CObservation2DRangeScan> scans;
	for (auto& ps : loadPosedScans(rawlog))
		if (ps.scan.sensorLabel == "LASER" || !isCarmenLog(path)) scans.push_back(std::move(ps.scan));
	if (!tmpDir.empty()) fs::remove_all(tmpDir);
	return scans;
}

std::vector<TRealRow> runReal(const std::vector<std::unique_ptr<CLineExtractor>>& extractors,
							  const std::vector<std::string>& logs, int repetitions)
{
	std::vector<TRealRow> rows;
	for (const auto& log : logs)
	{
		if (!fs::exists(log))
		{
			std::cerr << "hslam-bench lines: skipping missing " << log << "\n";
			continue;
		}
		const auto scans = loadScans(log);
		for (const auto& ex : extractors)
		{
			TRealRow row;
			row.log = fs::path(log).filename().string();
			row.method = ex->name();
			row.scans = scans.size();
			mrpt::random::getRandomGenerator().randomize(1234);
			for (const auto& scan : scans)
			{
				const TLineSegmentList lines = ex->extract(scan);
				row.validPoints += features::validScanPoints(scan).size();
				row.lines += lines.size();
				for (const auto& l : lines)
				{
					row.linePoints += l.point_count;
					row.sumRms_m += l.fit_rms_m;
				}
			}
			size_t sink = 0;
			const double t_s = bestTimeOf(repetitions, [&] {
				for (const auto& scan : scans) sink += ex->extract(scan).size();
			});
			row.us_per_scan = scans.empty() ? 0 : 1e6 * t_s / static_cast<double>(scans.size()) + 0 * static_cast<double>(sink);
			rows.push_back(row);
		}
	}
	return rows;
}

std::vector<std::string> defaultLogs()
{
	std::vector<std::string> logs;
	for (const char* name : {"intel", "aces", "csail"})
		logs.push_back(std::string("../shared/datasets/carmen/") + name + "-corrected.log.gz");
	return logs;
}
}  // namespace

int runLinesSuite(const std::vector<std::string>& inputs, int repetitions)
{
	const auto extractors = defaultExtractors();
	const auto synthetic = runSynthetic(extractors, repetitions);
	std::cout << "Suite lines: line extraction, thesis table 3 environments (" << kTrials
			  << " noisy views each, sigma " << kSigma_m * 100 << " cm, noisy wall " << kNoisySigma_m * 100
			  << " cm), best of " << repetitions << " runs\n"
			  << "found = true wall matched within 5 cm / 3 deg with >= 50 % overlap (one-to-one); FP = unmatched "
				 "extracted segment\n\n"
			  << std::left << std::setw(9) << "scene" << std::setw(12) << "method" << std::right << std::setw(12)
			  << "found/scan" << std::setw(9) << "FP/scan" << std::setw(8) << "recall" << std::setw(10) << "precision"
			  << std::setw(7) << "F1" << std::setw(12) << "endpt mm" << std::setw(10) << "us/scan" << "\n";
	std::map<std::string, features::TLineScore> pooled;
	std::map<std::string, double> synthUs;
	for (const auto& r : synthetic)
	{
		const double n = kTrials;
		std::ostringstream found;
		found << std::fixed << std::setprecision(2) << r.total.found / n << "/" << std::setprecision(0)
			  << r.total.truth / n;
		std::cout << std::left << std::setw(9) << r.scene << std::setw(12) << r.method << std::right << std::setw(12)
				  << found.str() << std::fixed << std::setprecision(2) << std::setw(9)
				  << r.total.false_positives / n << std::setprecision(3) << std::setw(8) << r.total.recall()
				  << std::setw(10) << r.total.precision() << std::setw(7) << r.total.f1() << std::setprecision(1)
				  << std::setw(12) << 1000 * r.total.meanEndpointError_m() << std::setw(10) << r.us_per_scan << "\n";
		accumulate(pooled[r.method], r.total);
		synthUs[r.method] += r.us_per_scan / 3;
	}

	std::vector<std::string> logs = inputs.empty() ? defaultLogs() : inputs;
	const auto real = runReal(extractors, logs, repetitions);
	std::map<std::string, std::pair<double, size_t>> realUs;  // sum of us, scans
	if (!real.empty())
	{
		std::cout << "\nReal scans (no ground truth): lines per scan, share of valid points on a line, mean fit RMS\n\n"
				  << std::left << std::setw(28) << "log" << std::setw(12) << "method" << std::right << std::setw(7)
				  << "scans" << std::setw(11) << "lines/scan" << std::setw(9) << "covered" << std::setw(10)
				  << "rms mm" << std::setw(10) << "us/scan" << "\n";
		for (const auto& r : real)
		{
			std::cout << std::left << std::setw(28) << r.log.substr(0, 27) << std::setw(12) << r.method << std::right
					  << std::setw(7) << r.scans << std::fixed << std::setprecision(2) << std::setw(11)
					  << static_cast<double>(r.lines) / std::max<size_t>(1, r.scans) << std::setprecision(3)
					  << std::setw(9) << static_cast<double>(r.linePoints) / std::max<size_t>(1, r.validPoints)
					  << std::setprecision(1) << std::setw(10) << 1000 * r.sumRms_m / std::max<size_t>(1, r.lines)
					  << std::setw(10) << r.us_per_scan << "\n";
			realUs[r.method].first += r.us_per_scan * static_cast<double>(r.scans);
			realUs[r.method].second += r.scans;
		}
	}
	std::cout << std::defaultfloat << std::setprecision(6) << "\n";
	for (const auto& ex : extractors)
	{
		const std::string m = ex->name();
		const auto& p = pooled[m];
		std::cout << "lines_f1_" << m << "=" << p.f1() << "\nlines_recall_" << m << "=" << p.recall()
				  << "\nlines_fp_per_scan_" << m << "=" << p.false_positives / (3.0 * kTrials) << "\nlines_endpoint_mm_"
				  << m << "=" << 1000 * p.meanEndpointError_m() << "\nlines_us_per_scan_synthetic_" << m << "="
				  << synthUs[m] << "\n";
		const auto& ru = realUs[m];
		// real scans when there are any (the representative case), else synthetic
		std::cout << "lines_us_per_scan_" << m << "=" << (ru.second ? ru.first / ru.second : synthUs[m]) << "\n";
	}
	return 0;
}

}  // namespace hslam::bench
