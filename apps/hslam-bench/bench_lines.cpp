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
 * scan count. MRPT's RANSAC uses MRPT's global random generator, seeded here.
 * The extra row "deriv-thesis" runs the derivative method with the thesis'
 * own settings where ours deviate (see CDerivativeLineExtractor.h). */
#include "bench_common.h"
#include "bench_report.h"

#include <hslam/common/options_io.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/features/CLineExtractor.h>
#include <hslam/benchdata/line_scenes.h>
#include <hslam/benchdata/line_scoring.h>
#include <hslam/io/carmen_import.h>
#include <hslam/features/scan_points.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/random/RandomGenerators.h>

#include <algorithm>
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
	benchdata::TLineScore total;  //!< summed over trials
	double us_per_scan = 0;
};

void accumulate(benchdata::TLineScore& total, const benchdata::TLineScore& s)
{
	total.truth += s.truth;
	total.extracted += s.extracted;
	total.found += s.found;
	total.false_positives += s.false_positives;
	total.sum_endpoint_error_m += s.sum_endpoint_error_m;
	total.max_endpoint_error_m = std::max(total.max_endpoint_error_m, s.max_endpoint_error_m);
}

struct TNamedExtractor
{
	std::string label;
	std::unique_ptr<CLineExtractor> extractor;
};

/** The three methods with default options, then "deriv-thesis": the
 * derivative method with the thesis' settings where ours deviate (step 1, no
 * absolute peak floor, guard split / RMS limits effectively off). */
std::vector<TNamedExtractor> benchExtractors()
{
	const mrpt::config::CConfigFileMemory empty;
	std::vector<TNamedExtractor> out;
	for (const auto& m : features::lineExtractorMethods())
		out.push_back({m, features::createLineExtractor(m, empty, features::lineExtractorSection(m))});
	const mrpt::config::CConfigFileMemory thesis(std::string(
		"[d]\nderivative_step_deg = 1\nmin_peak = 0\nsplit_distance_m = 1\nmerge_rms_growth = 100\n"
		"max_fit_rms_m = 1\n"));
	out.push_back({"deriv-thesis", features::createLineExtractor("derivative", thesis, "d")});
	return out;
}

std::vector<TSyntheticRow> runSynthetic(const std::vector<TNamedExtractor>& extractors, int repetitions)
{
	std::vector<TSyntheticRow> rows;
	std::mt19937 rng(42);
	std::uniform_real_distribution<double> jitter(-1, 1);
	for (const auto& scene : benchdata::thesisTable3Scenes(kSigma_m, kNoisySigma_m))
	{
		std::vector<benchdata::TSyntheticScan> sims;
		for (int t = 0; t < kTrials; ++t)
		{
			const mrpt::poses::CPose2D pose(0.1 * jitter(rng), 0.1 * jitter(rng), 3.0 * M_PI / 180 * jitter(rng));
			sims.push_back(benchdata::simulateScan(scene.walls, pose, {}, static_cast<uint32_t>(1000 + t)));
		}
		for (const auto& [label, ex] : extractors)
		{
			TSyntheticRow row{scene.name, label, {}, 0};
			mrpt::random::getRandomGenerator().randomize(1234);
			for (const auto& sim : sims)
				accumulate(row.total, benchdata::scoreLines(benchdata::visibleWalls(sim, 5, 0.2), ex->extract(sim.scan)));
			const double t_s = bestTimeOf(repetitions, [&] {
				for (const auto& sim : sims) (void)ex->extract(sim.scan);  // virtual call: not elided
			});
			row.us_per_scan = 1e6 * t_s / static_cast<double>(sims.size());
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

struct TRealLog
{
	std::vector<mrpt::obs::CObservation2DRangeScan> scans;
	/** Reference (corrected) pose of each scan; empty if the log has none. */
	std::vector<mrpt::poses::CPose2D> reference;
};

/** Front laser scans of a rawlog or CARMEN log; for CARMEN logs also the
 * reference poses (the importer's TUM file has one line per front scan). */
TRealLog loadScans(const std::string& path)
{
	std::string rawlog = path;
	fs::path tmpDir;
	TRealLog log;
	common::TTrajectory2D reference;
	if (isCarmenLog(path))
	{
		tmpDir = fs::temp_directory_path() / ("hslam-bench-lines-" + std::to_string(std::random_device{}()));
		fs::create_directories(tmpDir);
		rawlog = (tmpDir / "scans.rawlog").string();
		io::convertCarmenLog(path, rawlog, (tmpDir / "ref.tum").string(), {});
		reference = common::readTumFile((tmpDir / "ref.tum").string());
	}
	for (auto& ps : loadPosedScans(rawlog))
		if (ps.scan.sensorLabel == "LASER" || !isCarmenLog(path)) log.scans.push_back(std::move(ps.scan));
	if (!tmpDir.empty()) fs::remove_all(tmpDir);
	if (reference.size() == log.scans.size())
		for (const auto& r : reference) log.reference.emplace_back(r.pose);
	return log;
}

/** Repeatability of lines between consecutive scans with reference poses. */
struct TRepeatability
{
	size_t lines = 0;  //!< lines >= kRepeatMinLength_m in scan k+1 (k+1 with a reference)
	size_t partnered = 0;  //!< ... with a partner line in scan k
	std::vector<double> endErrorReal_m, endErrorOccluded_m;  //!< along-line end point differences
};

constexpr double kRepeatMinLength_m = 1.0, kRepeatMaxOffset_m = 0.1, kRepeatMaxAngle_rad = 3.0 * M_PI / 180;

/** Adds the comparison of `cur` (scan k+1) with `prev` (scan k) moved into the frame of k+1 by `prevInCur`. */
void compareConsecutive(const TLineSegmentList& prev, const TLineSegmentList& cur, const mrpt::poses::CPose2D& prevInCur,
						TRepeatability& rep)
{
	for (const auto& c : cur)
	{
		if (c.length_m() < kRepeatMinLength_m) continue;
		++rep.lines;
		const double L = c.length_m(), ux = (c.p1.x - c.p0.x) / L, uy = (c.p1.y - c.p0.y) / L;
		auto along = [&](const mrpt::math::TPoint2D& p) { return (p.x - c.p0.x) * ux + (p.y - c.p0.y) * uy; };
		for (const auto& p : prev)
		{
			mrpt::math::TPoint2D q0, q1;
			prevInCur.composePoint(p.p0.x, p.p0.y, q0.x, q0.y);
			prevInCur.composePoint(p.p1.x, p.p1.y, q1.x, q1.y);
			if (std::abs(c.distanceTo(q0)) > kRepeatMaxOffset_m || std::abs(c.distanceTo(q1)) > kRepeatMaxOffset_m) continue;
			const double dir = std::atan2(q1.y - q0.y, q1.x - q0.x), cdir = std::atan2(uy, ux);
			const double dAngle = std::abs(std::remainder(dir - cdir, M_PI));
			if (dAngle > kRepeatMaxAngle_rad) continue;
			double a0 = along(q0), a1 = along(q1);
			bool occ0 = p.p0_occluded, occ1 = p.p1_occluded;
			if (a0 > a1)
			{
				std::swap(a0, a1);
				std::swap(occ0, occ1);
			}
			if (a1 < 0 || a0 > L) continue;  // no overlap
			++rep.partnered;
			// same wall end seen twice: c.p0 <-> along 0, c.p1 <-> along L
			(c.p0_occluded || occ0 ? rep.endErrorOccluded_m : rep.endErrorReal_m).push_back(std::abs(a0));
			(c.p1_occluded || occ1 ? rep.endErrorOccluded_m : rep.endErrorReal_m).push_back(std::abs(a1 - L));
			break;
		}
	}
}

double median(std::vector<double> v)
{
	if (v.empty()) return 0;
	std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
	return v[v.size() / 2];
}

struct TRealRow
{
	std::string log, method;
	size_t scans = 0, lines = 0, validPoints = 0, linePoints = 0, ends = 0, occludedEnds = 0;
	double sumRms_m = 0, us_per_scan = 0;
	TRepeatability repeat;
};

std::vector<TRealRow> runReal(const std::vector<TNamedExtractor>& extractors,
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
		const TRealLog data = loadScans(log);
		const auto& scans = data.scans;
		for (const auto& [label, ex] : extractors)
		{
			TRealRow row;
			row.log = fs::path(log).filename().string();
			row.method = label;
			row.scans = scans.size();
			mrpt::random::getRandomGenerator().randomize(1234);
			TLineSegmentList previous;
			for (size_t k = 0; k < scans.size(); ++k)
			{
				const auto& scan = scans[k];
				const TLineSegmentList lines = ex->extract(scan);
				row.validPoints += common::makeRangeData(scan).points.size();
				row.lines += lines.size();
				for (const auto& l : lines)
				{
					row.linePoints += l.point_count;
					row.sumRms_m += l.fit_rms_m;
					row.ends += 2;
					row.occludedEnds += l.p0_occluded + l.p1_occluded;
				}
				if (k > 0 && !data.reference.empty())
					compareConsecutive(previous, lines, data.reference[k - 1] - data.reference[k], row.repeat);
				previous = lines;
			}
			const double t_s = bestTimeOf(repetitions, [&] {
				for (const auto& scan : scans) (void)ex->extract(scan);  // virtual call: not elided
			});
			row.us_per_scan = scans.empty() ? 0 : 1e6 * t_s / static_cast<double>(scans.size());
			rows.push_back(row);
		}
	}
	return rows;
}

/** intel, aces and csail from ../shared/datasets/carmen, looked up from the
 * worktree root, build/ or build/bin/ (the first folder that exists). */
std::vector<std::string> defaultLogs()
{
	std::string dir = "../shared/datasets/carmen";
	for (const char* candidate : {"../shared/datasets/carmen", "../../shared/datasets/carmen", "../../../shared/datasets/carmen"})
		if (fs::is_directory(candidate))
		{
			dir = candidate;
			break;
		}
	std::vector<std::string> logs;
	for (const char* name : {"intel", "aces", "csail"}) logs.push_back(dir + "/" + name + "-corrected.log.gz");
	return logs;
}
/** Per method: synthetic scores pooled over the scenes, and mean time per scan. */
struct TSyntheticTotals
{
	std::map<std::string, benchdata::TLineScore> pooled;
	std::map<std::string, double> us_per_scan;
};

TSyntheticTotals printSyntheticTable(const std::vector<TSyntheticRow>& rows, int repetitions)
{
	std::cout << "Suite lines: line extraction, thesis table 3 environments (" << kTrials
			  << " noisy views each, sigma " << kSigma_m * 100 << " cm, noisy wall " << kNoisySigma_m * 100
			  << " cm), best of " << repetitions << " runs\n"
			  << "found = true wall matched within 5 cm / 3 deg with >= 50 % overlap (one-to-one); FP = unmatched "
				 "extracted segment\n\n";
	const CReportTable table(std::cout, {{"scene", 9, true},
										 {"method", 12, true},
										 {"found/scan", 12},
										 {"FP/scan", 9},
										 {"recall", 8},
										 {"precision", 10},
										 {"F1", 7},
										 {"endpt mm", 12},
										 {"us/scan", 10}});
	table.printHeader();
	TSyntheticTotals totals;
	for (const auto& r : rows)
	{
		const double n = kTrials;
		table.printRow({r.scene, r.method, fixed(r.total.found / n, 2) + "/" + fixed(r.total.truth / n, 0),
						fixed(r.total.false_positives / n, 2), fixed(r.total.recall(), 3), fixed(r.total.precision(), 3),
						fixed(r.total.f1(), 3), fixed(1000 * r.total.meanEndpointError_m(), 1), fixed(r.us_per_scan, 1)});
		accumulate(totals.pooled[r.method], r.total);
		totals.us_per_scan[r.method] += r.us_per_scan / 3;
	}
	return totals;
}

/** Per method on the real logs: time per scan pooled over scans, and repeatability. */
struct TRealTotals
{
	std::map<std::string, std::pair<double, size_t>> us;  //!< sum of us, scans
	std::map<std::string, TRepeatability> repeat;
};

void printRealRow(const CReportTable& table, const TRealRow& r)
{
	const auto ratio = [](size_t a, size_t b) { return static_cast<double>(a) / std::max<size_t>(1, b); };
	table.printRow({r.log.substr(0, 23), r.method, std::to_string(r.scans), fixed(ratio(r.lines, r.scans), 2),
					fixed(ratio(r.linePoints, r.validPoints), 3), fixed(1000 * r.sumRms_m / std::max<size_t>(1, r.lines), 1),
					fixed(ratio(r.occludedEnds, r.ends), 2), fixed(ratio(r.repeat.partnered, r.repeat.lines), 2),
					fixed(1000 * median(r.repeat.endErrorReal_m), 0) + "/" + fixed(1000 * median(r.repeat.endErrorOccluded_m), 0),
					fixed(r.us_per_scan, 1)});
}

TRealTotals printRealTable(const std::vector<TRealRow>& rows)
{
	TRealTotals totals;
	if (rows.empty()) return totals;
	std::cout << "\nReal scans (no ground-truth lines): lines per scan; covered = share of valid points on a line;\n"
				 "rms = mean fit RMS; occl = share of line ends flagged occluded; repeat = share of lines >= 1 m\n"
				 "with a partner in the previous scan moved by the reference poses (10 cm, 3 deg, overlapping);\n"
				 "end mm = median along-line distance of partnered ends, real (neither flagged) / occluded\n\n";
	const CReportTable table(std::cout, {{"log", 24, true},
										 {"method", 11, true},
										 {"scans", 6},
										 {"lines/scan", 11},
										 {"covered", 9},
										 {"rms mm", 8},
										 {"occl", 7},
										 {"repeat", 8},
										 {"end mm r/o", 14},
										 {"us/scan", 10}});
	table.printHeader();
	for (const auto& r : rows)
	{
		printRealRow(table, r);
		auto& pooledRepeat = totals.repeat[r.method];
		pooledRepeat.lines += r.repeat.lines;
		pooledRepeat.partnered += r.repeat.partnered;
		totals.us[r.method].first += r.us_per_scan * static_cast<double>(r.scans);
		totals.us[r.method].second += r.scans;
	}
	return totals;
}

void printLinesKeys(TSyntheticTotals& synthetic, TRealTotals& real)
{
	std::cout << "\n";
	CKeyValueLines keys(std::cout);
	for (const auto& m : features::lineExtractorMethods())
	{
		const auto& p = synthetic.pooled[m];
		keys("lines_f1_" + m, p.f1())("lines_recall_" + m, p.recall())(
			"lines_fp_per_scan_" + m, p.false_positives / (3.0 * kTrials))(
			"lines_endpoint_mm_" + m, 1000 * p.meanEndpointError_m())(
			"lines_us_per_scan_synthetic_" + m, synthetic.us_per_scan[m]);
		const auto& ru = real.us[m];
		// real scans when there are any (the representative case), else synthetic
		keys("lines_us_per_scan_" + m, ru.second ? ru.first / ru.second : synthetic.us_per_scan[m]);
		if (real.repeat[m].lines)
			keys("lines_real_repeatability_" + m, static_cast<double>(real.repeat[m].partnered) / real.repeat[m].lines);
	}
}
}  // namespace

int runLinesSuite(const std::vector<std::string>& inputs, int repetitions)
{
	const auto extractors = benchExtractors();
	TSyntheticTotals synthetic = printSyntheticTable(runSynthetic(extractors, repetitions), repetitions);
	const std::vector<std::string> logs = inputs.empty() ? defaultLogs() : inputs;
	TRealTotals real = printRealTable(runReal(extractors, logs, repetitions));
	printLinesKeys(synthetic, real);
	return 0;
}

}  // namespace hslam::bench
