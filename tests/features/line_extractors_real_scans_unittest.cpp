/* The three extractors on real laser scans: MRPT's sample rawlog (SICK,
 * Malaga) and the CARMEN intel log converted with our importer. No ground
 * truth lines exist, so the tests check what must hold on any real scan and
 * that the methods agree with each other. */
#include "line_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/benchdata/line_scoring.h>
#include <hslam/features/scan_points.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <iostream>

using namespace hslam::features;
using namespace hslam::benchdata;

namespace
{
std::vector<mrpt::obs::CObservation2DRangeScan> readScans(const std::string& rawlog, size_t maxScans,
														  const std::string& label)
{
	std::vector<mrpt::obs::CObservation2DRangeScan> scans;
	hslam::io::CRawlogReader reader(rawlog);
	hslam::io::TRawlogEntry entry;
	auto take = [&](const mrpt::obs::CObservation::Ptr& o) {
		auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o);
		if (s && (label.empty() || s->sensorLabel == label) && scans.size() < maxScans) scans.push_back(*s);
	};
	while (scans.size() < maxScans && reader.next(entry))
	{
		if (entry.observation) take(entry.observation);
		if (entry.frame)
			for (const auto& o : *entry.frame) take(o);
	}
	return scans;
}

/** Invariants of every line of a real scan; returns the number of lines. */
size_t checkLines(const mrpt::obs::CObservation2DRangeScan& scan, const TLineSegmentList& lines,
				  const std::string& method)
{
	const TScanPoints pts = hslam::common::makeRangeData(scan).points;
	for (size_t k = 0; k < lines.size(); ++k)
	{
		const TLineSegment& l = lines[k];
		EXPECT_GE(l.point_count, 5u) << method;
		EXPECT_GE(l.length_m(), 0.2) << method;
		EXPECT_LE(l.first_beam, l.last_beam) << method;
		EXPECT_TRUE(hslam::common::isValidReturn(scan, l.first_beam)) << method;
		EXPECT_TRUE(hslam::common::isValidReturn(scan, l.last_beam)) << method;
		if (k > 0)
		{
			EXPECT_LE(lines[k - 1].first_beam, l.first_beam) << method << ": lines ordered by first beam";
		}
		EXPECT_GE(l.rho_m, 0.0);
		EXPECT_TRUE(l.alpha_rad > -M_PI && l.alpha_rad <= M_PI);
		// endpoints lie on the line and no more than a few noise sigmas off
		// the measured end points (projections), which are inside the scan's reach
		EXPECT_NEAR(l.distanceTo(l.p0), 0.0, 1e-6);
		EXPECT_NEAR(l.distanceTo(l.p1), 0.0, 1e-6);
		EXPECT_LT(std::hypot(l.p0.x, l.p0.y), scan.maxRange + 0.5);
		// fit bounds by construction: derivative max_fit_rms_m 4 cm, IEP every
		// point within 10 cm of the chord, RANSAC inliers within 5 cm of its line
		const double maxRms = method == "derivative" ? 0.04 : method == "iep" ? 0.1 : 0.05;
		EXPECT_LE(l.fit_rms_m, maxRms) << method;
	}
	return lines.size();
}

void checkRealScans(const std::vector<mrpt::obs::CObservation2DRangeScan>& scans, double minLinesPerScan,
					double minAgreement)
{
	ASSERT_FALSE(scans.empty());
	std::map<std::string, std::vector<TLineSegmentList>> results;
	for (const auto& m : lineExtractorMethods())
	{
		const auto ex = test::defaultExtractor(m);
		size_t total = 0;
		for (const auto& scan : scans)
		{
			results[m].push_back(ex->extract(scan));
			total += checkLines(scan, results[m].back(), m);
		}
		const double perScan = static_cast<double>(total) / scans.size();
		std::cout << "  " << m << ": " << perScan << " lines per scan\n";
		EXPECT_GE(perScan, minLinesPerScan) << m;
	}
	// agreement: derivative lines longer than 1 m that IEP also finds (same test as
	// the synthetic scoring, with the IEP line as "truth")
	size_t longLines = 0, agreed = 0;
	for (size_t i = 0; i < scans.size(); ++i)
		for (const auto& d : results["derivative"][i])
		{
			if (d.length_m() < 1.0) continue;
			++longLines;
			TVisibleWall t;
			t.p0 = d.p0;
			t.p1 = d.p1;
			agreed += scoreLines({t}, results["iep"][i]).found;
		}
	ASSERT_GT(longLines, 0u);
	std::cout << "  derivative lines >= 1 m also found by IEP: " << agreed << "/" << longLines << "\n";
	EXPECT_GE(static_cast<double>(agreed) / longLines, minAgreement) << agreed << "/" << longLines;
}
}  // namespace

TEST(LineExtractorsRealScans, MrptSampleRawlog)
{
	const auto scans =
		readScans(std::string(HSLAM_MRPT_DATASETS_DIR) + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog", 150, "");
	// measured (150 scans): derivative 10.4, iep 14.6, ransac 10.6 lines per scan;
	// 659 of 680 derivative lines >= 1 m also found by IEP (97 %)
	checkRealScans(scans, 7.0, 0.9);
}

TEST(LineExtractorsRealScans, CarmenIntelLog)
{
	hslam::testing::CTempDir dir;
	hslam::io::convertCarmenLog(std::string(HSLAM_SHARED_DATASETS_DIR) + "/carmen/intel-corrected.log.gz",
								dir.file("intel.rawlog"), dir.file("intel.tum"), {});
	const auto scans = readScans(dir.file("intel.rawlog"), 300, "LASER");
	ASSERT_EQ(scans.size(), 300u);
	// measured (300 scans): derivative 6.1, iep 6.9, ransac 6.1 lines per scan;
	// 702 of 762 derivative lines >= 1 m also found by IEP (92 %)
	checkRealScans(scans, 4.5, 0.85);
}
