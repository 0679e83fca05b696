/* hslam-evaluate refuses what would give a meaningless number (issue 15,
 * items 5 and 6): --json naming an input (the input stays intact), two poses
 * (any two poses align exactly: ATE 0), a coordinate that overflows (inf). */
#include <gtest/gtest.h>
#include <hslam/common/tum_trajectory.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <fstream>
#include <sstream>

#include "trajectory_fixtures.h"

using namespace hslam::eval;
using hslam::testing::CTempDir;

namespace
{
std::string text(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

int evaluate(const CTempDir& dir, const std::string& args)
{
	return hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-evaluate " + args + " >" + dir.file("out.txt") +
									  " 2>" + dir.file("err.txt"));
}
}  // namespace

TEST(HslamEvaluateRefusals, JsonOverAnInputIsRefused)
{
	CTempDir dir;
	hslam::common::writeTumFile(dir.file("ref.tum"), fixtures::straightLine(20, 0.1));
	hslam::common::writeTumFile(dir.file("est.tum"), fixtures::straightLine(20, 0.1));
	const std::string before = text(dir.file("est.tum"));
	EXPECT_EQ(evaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --json " + dir.file("est.tum")), 1);
	EXPECT_NE(text(dir.file("err.txt")).find("--json '" + dir.file("est.tum") + "' is the input"), std::string::npos)
		<< text(dir.file("err.txt"));
	EXPECT_EQ(text(dir.file("est.tum")), before);
	EXPECT_EQ(evaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum") + " --json " + dir.file("./ref.tum")), 1);
}

TEST(HslamEvaluateRefusals, TwoPosesAreTooFew)
{
	CTempDir dir;
	hslam::common::writeTumFile(dir.file("ref.tum"), fixtures::straightLine(2, 0.1));
	hslam::common::writeTumFile(dir.file("est.tum"), fixtures::transformed(fixtures::straightLine(2, 0.3), mrpt::poses::CPose2D(1, 2, 0.3)));
	EXPECT_EQ(evaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum")), 1);
	EXPECT_NE(text(dir.file("err.txt")).find("only 2 pose(s) matched"), std::string::npos) << text(dir.file("err.txt"));
	EXPECT_NE(text(dir.file("err.txt")).find("at least 3 needed"), std::string::npos);
	EXPECT_EQ(text(dir.file("out.txt")).find("ATE"), std::string::npos);
}

TEST(HslamEvaluateRefusals, HugeCoordinateIsRefusedNamingThePose)
{
	CTempDir dir;
	auto est = fixtures::straightLine(20, 0.1);
	hslam::common::writeTumFile(dir.file("ref.tum"), est);
	est[4].pose.x = 1e308;
	hslam::common::writeTumFile(dir.file("est.tum"), est);
	EXPECT_EQ(evaluate(dir, dir.file("ref.tum") + " " + dir.file("est.tum")), 1);
	EXPECT_NE(text(dir.file("err.txt")).find("est.tum': pose 5: coordinates must be finite"), std::string::npos)
		<< text(dir.file("err.txt"));
}
