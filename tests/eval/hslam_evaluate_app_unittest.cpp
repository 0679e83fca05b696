/* hslam tests: the hslam-evaluate app end to end on files in a temp folder. */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
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
