/* hslam tests: the hslam-evaluate app end to end on files in a temp folder. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CRawlogObservationWriter.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <fstream>
#include <sstream>
#include <string>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::testing::CTempDir;
using hslam::testing::runCommand;

namespace
{
std::string readText(const std::string& path) { return hslam::testing::readTextFile(path); }

/** Runs the app with `args`, stdout/stderr into files in `dir`. */
int runEvaluate(const CTempDir& dir, const std::string& args)
{
	return runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-evaluate " + args + " >" + dir.file("out.txt") +
					  " 2>" + dir.file("err.txt"));
}

}  // namespace

TEST(HslamEvaluateApp, EvaluatesTwoFilesAndWritesJson)
{
	CTempDir dir;
	const auto ref = fixtures::windingPath(120);
	auto est = fixtures::transformed(ref, mrpt::poses::CPose2D(5.0, -3.0, 0.5));
	est.erase(est.begin() + 50);  // one estimate pose missing
	for (auto& p : est) p.t_s += 0.005;  // clock offset below max_dt
	hslam::common::writeTumFile(dir.file("ref.tum"), ref);
	hslam::common::writeTumFile(dir.file("est.tum"), est);

	ASSERT_EQ(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --json " + dir.file("e.json")),
			  0)
		<< readText(dir.file("err.txt"));
	const std::string out = readText(dir.file("out.txt"));
	EXPECT_NE(out.find("matched   119 poses"), std::string::npos) << out;
	EXPECT_NE(out.find("5m"), std::string::npos) << out;
	const std::string json = readText(dir.file("e.json"));
	EXPECT_NE(json.find("\"matched\": 119,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"unmatched_reference\": 1,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"ate_rmse_m\": "), std::string::npos) << json;
}

TEST(HslamEvaluateApp, MalformedLineFailsWithFileAndLine)
{
	CTempDir dir;
	hslam::common::writeTumFile(dir.file("ref.tum"), fixtures::straightLine(10, 0.1));
	std::ofstream(dir.file("bad.tum")) << "100.0 0 0 0 0 0 0 1\n100.1 0.1 zero 0 0 0 0 1\n";

	EXPECT_NE(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("bad.tum")), 0);
	const std::string err = readText(dir.file("err.txt"));
	EXPECT_NE(err.find(dir.file("bad.tum") + ":2"), std::string::npos) << err;
	EXPECT_EQ(err.find('\n'), err.size() - 1) << "one line expected: " << err;
}

TEST(HslamEvaluateApp, DisjointTimeRangesFailWithBothRanges)
{
	CTempDir dir;
	hslam::common::writeTumFile(dir.file("ref.tum"), fixtures::straightLine(10, 0.1, 1700000000.0));
	hslam::common::writeTumFile(dir.file("est.tum"), fixtures::straightLine(10, 0.1, 5.0));

	EXPECT_NE(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum")), 0);
	const std::string err = readText(dir.file("err.txt"));
	for (const std::string& part : {dir.file("ref.tum"), dir.file("est.tum"), std::string("[1700000000.000, "),
								   std::string("[5.000, 5.900]")})
		EXPECT_NE(err.find(part), std::string::npos) << part << " not in: " << err;
}

TEST(HslamEvaluateApp, HelpSucceedsAndBadArgumentsFail)
{
	CTempDir dir;
	EXPECT_EQ(runEvaluate(dir, "--help"), 0);
	EXPECT_NE(readText(dir.file("out.txt")).find("--max-dt"), std::string::npos);
	EXPECT_NE(runEvaluate(dir, "only_one.tum"), 0);
	EXPECT_NE(runEvaluate(dir, "a.tum b.tum --max-dt fast"), 0);
	EXPECT_NE(readText(dir.file("err.txt")).find("--max-dt"), std::string::npos);
	EXPECT_NE(runEvaluate(dir, dir.file("missing.tum") + " b.tum"), 0);
	EXPECT_NE(readText(dir.file("err.txt")).find("missing.tum"), std::string::npos);
}

TEST(HslamEvaluateApp, RawlogComparesHowWellEachTrajectoryExplainsTheScans)
{
	// A robot standing still in a round room of radius 2 m: three identical
	// scans. The reference says it stood still; the estimate moves it 0.1 m
	// at the last scan, which misfits that pair by the mean radial part of
	// the shift, 0.1 * 2 / pi = 0.064 m (> clearly_m = 0.03).
	CTempDir dir;
	{
		hslam::io::CRawlogObservationWriter out(dir.file("room.rawlog"));
		for (int k = 0; k < 3; ++k)
		{
			mrpt::obs::CObservation2DRangeScan scan;
			scan.sensorLabel = "LASER";
			scan.timestamp = mrpt::Clock::fromDouble(100.0 + 0.1 * k);
			scan.aperture = static_cast<float>(M_PI);
			scan.maxRange = 30;
			scan.resizeScan(181);
			for (size_t b = 0; b < 181; ++b) scan.setScanRange(b, 2.0f), scan.setScanRangeValidity(b, true);
			out.write(scan);
		}
	}
	auto ref = fixtures::straightLine(3, 0.0);
	auto est = ref;
	est[2].pose.x += 0.1;
	hslam::common::writeTumFile(dir.file("ref.tum"), ref);
	hslam::common::writeTumFile(dir.file("est.tum"), est);

	ASSERT_EQ(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --rawlog " + dir.file("room.rawlog") +
								   " --json " + dir.file("e.json")),
			  0)
		<< readText(dir.file("err.txt"));
	const std::string out = readText(dir.file("out.txt"));
	EXPECT_NE(out.find("estimate clearly worse: 1 pairs"), std::string::npos) << out;
	const std::string json = readText(dir.file("e.json"));
	EXPECT_NE(json.find("\"scan_pairs\": 2,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"scan_misfit_reference_mean_m\": 0,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"scan_pairs_estimate_clearly_worse\": 1,"), std::string::npos) << json;

	// --laser-label alone means nothing: refused, not ignored
	EXPECT_NE(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --laser-label LASER"), 0);
	EXPECT_NE(readText(dir.file("err.txt")).find("--laser-label needs --rawlog"), std::string::npos);
	// a label the rawlog does not have names the file
	EXPECT_NE(runEvaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --rawlog " + dir.file("room.rawlog") +
								   " --laser-label SICK"),
			  0);
	EXPECT_NE(readText(dir.file("err.txt")).find("room.rawlog: no scan has the label 'SICK'"), std::string::npos);
}
