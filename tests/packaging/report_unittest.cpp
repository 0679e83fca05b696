// Unit tests of the run summary (summary.json), the HTML escaping of the
// report, the data-folder lookup of installed apps and the version text.
#include <gtest/gtest.h>
#include <hslam/common/data_paths.h>
#include <hslam/common/version.h>
#include <hslam/batch/html_report.h>
#include <hslam/batch/run_summary.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/version.h>

#include <filesystem>
#include <fstream>

using namespace hslam;

TEST(RunSummary, JsonWithoutReferenceHasNullAteAndEscapedWarnings)
{
	batch::TRunSummary s;
	s.input = "in \"quoted\".rawlog";
	s.scans = 12;
	s.wall_s = 0.6;
	s.ms_per_scan = 50.0;
	s.warnings = {"3 odometry gaps (motion unknown)", "tab\there"};
	const std::string json = batch::runSummaryToJson(s);
	EXPECT_NE(json.find("\"scans\": 12,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"ms_per_scan\": 50.000,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"input\": \"in \\\"quoted\\\".rawlog\","), std::string::npos) << json;
	EXPECT_NE(json.find("\"ate_rmse_m\": null,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"evaluated\": false,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"input_error\": null,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"warnings\": [\"3 odometry gaps (motion unknown)\", \"tab\\u0009here\"],"),
			  std::string::npos)
		<< json;
	EXPECT_NE(json.find("\"mrpt_version\": \"" + common::mrptBuildVersion() + "\""), std::string::npos);
	EXPECT_EQ(json.back(), '\n');
}

TEST(RunSummary, JsonWithReferenceCarriesAteAndTheEvaluationObject)
{
	batch::TRunSummary s;
	eval::TTrajectoryErrors e;
	e.matched = 7;
	e.ate.position_m.count = 7;
	e.ate.position_m.rmse = 0.125;
	e.ate.position_m.mean = 0.1;
	e.ate.position_m.max = 0.25;
	s.evaluation = e;
	const std::string json = batch::runSummaryToJson(s);
	EXPECT_NE(json.find("\"ate_rmse_m\": 0.125,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"ate_max_m\": 0.25,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"matched_poses\": 7,"), std::string::npos) << json;
	EXPECT_NE(json.find("\"evaluation\": {"), std::string::npos) << json;
}

TEST(HtmlReport, EscapesMarkup)
{
	EXPECT_EQ(batch::htmlEscape("a<b> & \"c\""), "a&lt;b&gt; &amp; &quot;c&quot;");
	EXPECT_EQ(batch::htmlEscape("plain"), "plain");
}

TEST(DataPaths, TheBuildTreeMirrorsTheInstalledLayout)
{
	// This test program is build/bin/test_packaging: its data folder is
	// build/share/hslam, whose config_ini is the source tree's (a link).
	EXPECT_EQ(common::executableDir(), std::filesystem::weakly_canonical(std::string(HSLAM_BINARY_DIR) + "/bin"));
	const auto ini = common::defaultConfigFile();
	ASSERT_TRUE(std::filesystem::exists(ini)) << ini;
	EXPECT_TRUE(std::filesystem::equivalent(ini, std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini"));
}

TEST(DataPaths, RelativePathsFallBackToTheDataFolderOnlyWhenMissingHere)
{
	hslam::testing::CTempDir dir;
	const auto cwd = std::filesystem::current_path();
	std::filesystem::current_path(dir.path());
	EXPECT_TRUE(std::filesystem::equivalent(common::resolveDataFile("config_ini/sim-lab.ini"),
											std::string(HSLAM_SOURCE_DIR) + "/config_ini/sim-lab.ini"));
	std::filesystem::create_directories("config_ini");
	std::ofstream("config_ini/sim-lab.ini") << "[simulation]\n";
	EXPECT_EQ(common::resolveDataFile("config_ini/sim-lab.ini"), "config_ini/sim-lab.ini");  // the local one wins
	EXPECT_EQ(common::resolveDataFile("no/such.ini"), "no/such.ini");  // left for the caller's error
	EXPECT_EQ(common::resolveDataFile("/abs/missing.ini"), "/abs/missing.ini");
	std::filesystem::current_path(cwd);
}

TEST(Version, NamesProjectAndMrptVersions)
{
	EXPECT_EQ("MRPT " + common::mrptBuildVersion(), std::string(MRPT_version_str));  // e.g. "MRPT 2.5.8"
	EXPECT_EQ(common::versionText(), common::projectVersion() + " (built against MRPT " + common::mrptBuildVersion() + ")");
	EXPECT_EQ(common::projectVersion().find_first_not_of("0123456789."), std::string::npos);
}
