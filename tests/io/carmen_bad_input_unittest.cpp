/* hslam-carmen2rawlog and convertCarmenLog on bad input (issue 15, items 2,
 * 4, 5, 6): an output that is the input is refused (the input intact), a log
 * without scans exits 3, a NUL byte costs one line (not the next scan), and
 * one outlier beam no longer switches off the no-return handling. */
#include <gtest/gtest.h>
#include <hslam/io/CRawlogReader.h>
#include <hslam/io/carmen_import.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>

#include "carmen_test_utils.h"

using namespace hslam::io;
namespace carmen = hslam::testing::carmen;

namespace
{
/** A corrected-style log of n scans of 10 beams; every 4th scan has one
 * beam at the no-return value 81.91 m. */
std::string smallLog(int n, double outlier_m = 0)
{
	std::string text = "PARAM robot_front_laser_max 81.9 nohost 0\n";
	for (int k = 0; k < n; ++k)
	{
		const mrpt::math::TPose2D p(0.1 * k, 0, 0);
		text += carmen::odom(p, 100.0 + k - 0.05);
		std::vector<double> ranges(10, 2.0 + 0.01 * k);
		if (k % 4 == 0) ranges[3] = 81.91;
		if (k == 5 && outlier_m > 0) ranges[7] = outlier_m;
		text += carmen::flaser(ranges, p, 100.0 + k, 100.0 + k);
		text += carmen::anchor(p);
	}
	return text;
}

int runApp(const hslam::testing::CTempDir& tmp, const std::string& args)
{
	return hslam::testing::runCommand(std::string(HSLAM_BIN_DIR) + "/hslam-carmen2rawlog " + args + " > '" +
									  tmp.file("out.txt") + "' 2> '" + tmp.file("err.txt") + "'");
}
}  // namespace

TEST(CarmenBadInput, OutputThatIsTheInputIsRefusedAndTheInputKept)
{
	hslam::testing::CTempDir tmp;
	const std::string in = tmp.file("in.log");
	carmen::writeText(in, smallLog(12));
	const std::string original = carmen::readText(in);
	std::filesystem::create_symlink(in, tmp.file("alias.log"));
	for (const std::string& args : {"'" + in + "' '" + in + "' --reference '" + tmp.file("r.tum") + "'",
								   "'" + in + "' '" + tmp.file("alias.log") + "' --reference '" + tmp.file("r.tum") + "'",
								   "'" + in + "' '" + tmp.file("o.rawlog") + "' --reference '" + in + "'",
								   "'" + in + "' '" + tmp.file("o.rawlog") + "' --reference '" + tmp.file("o.rawlog") + "'"})
	{
		EXPECT_EQ(runApp(tmp, args), 1) << args;
		const std::string err = carmen::readText(tmp.file("err.txt"));
		EXPECT_TRUE(err.find("refusing to overwrite an input") != std::string::npos ||
					err.find("two outputs name the same file") != std::string::npos)
			<< err;
		EXPECT_EQ(carmen::readText(in), original);
	}
	EXPECT_FALSE(std::filesystem::exists(tmp.file("o.rawlog")));
}

TEST(CarmenBadInput, LogWithOnlyParamLinesExitsThree)
{
	hslam::testing::CTempDir tmp;
	carmen::writeText(tmp.file("params.log"), "PARAM robot_front_laser_max 81.9 nohost 0\nPARAM a b nohost 0\n");
	EXPECT_EQ(runApp(tmp, "'" + tmp.file("params.log") + "' '" + tmp.file("o.rawlog") + "' --reference '" + tmp.file("o.tum") + "'"), 3);
	EXPECT_NE(carmen::readText(tmp.file("err.txt")).find("has no laser scan"), std::string::npos) << carmen::readText(tmp.file("err.txt"));
	EXPECT_NE(carmen::readText(tmp.file("out.txt")).find("scans written: 0 front"), std::string::npos);
}

TEST(CarmenBadInput, NulByteCostsOneLineNotTheNextScan)
{
	hslam::testing::CTempDir tmp;
	std::string text = smallLog(10);
	// A NUL inside the anchor ODOM line after the 3rd scan (line 10).
	const size_t at = text.find("ODOM", text.find("FLASER", text.find("FLASER", text.find("FLASER") + 1) + 1));
	text[at + 6] = '\0';
	carmen::writeText(tmp.file("nul.log"), text);
	TCarmenImportOptions strict;
	try
	{
		convertCarmenLog(tmp.file("nul.log"), tmp.file("s.rawlog"), tmp.file("s.tum"), strict);
		ADD_FAILURE() << "a NUL byte was accepted";
	}
	catch (const std::exception& e)
	{
		// The error names the line of the NUL (PARAM + 3 x 3 lines).
		EXPECT_NE(std::string(e.what()).find("nul.log:10:"), std::string::npos) << e.what();
	}
	TCarmenImportOptions lenient;
	lenient.lenient = true;
	const auto report = convertCarmenLog(tmp.file("nul.log"), tmp.file("l.rawlog"), tmp.file("l.tum"), lenient);
	EXPECT_EQ(report.malformedLinesSkipped, 1u);
	EXPECT_EQ(report.frontScans, 10u);  // before the fix: 9 (the next FLASER was glued to the NUL line)
}

TEST(CarmenBadInput, OneOutlierBeamKeepsNoReturnHandlingAndIsReported)
{
	hslam::testing::CTempDir tmp;
	carmen::writeText(tmp.file("o.log"), smallLog(40, 1e308));
	const auto report = convertCarmenLog(tmp.file("o.log"), tmp.file("o.rawlog"), tmp.file("o.tum"), {});
	ASSERT_TRUE(report.noReturn_m.has_value()) << report.rangeLimitsReason;
	EXPECT_DOUBLE_EQ(*report.noReturn_m, 81.91);
	EXPECT_EQ(report.rangeOutlierScans, 1u);
	const auto warned = std::count_if(report.warnings.begin(), report.warnings.end(), [](const std::string& w) {
		return w.find("1 scan(s) have ranges above the no-return value 81.91 m") != std::string::npos;
	});
	EXPECT_EQ(warned, 1);
	// In the rawlog: the 81.91 m beams and the outlier are invalid, the rest valid.
	CRawlogReader reader(tmp.file("o.rawlog"));
	TRawlogEntry e;
	size_t invalid = 0, valid = 0;
	while (reader.next(e))
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(e.observation))
			for (size_t i = 0; i < s->getScanSize(); ++i) (s->getScanRangeValidity(i) ? valid : invalid)++;
	EXPECT_EQ(invalid, 10u + 1u);
	EXPECT_EQ(valid, 40u * 10u - 11u);
}
