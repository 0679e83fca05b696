/* hslam tests: config_used.ini is the effective configuration. A batch job
 * on a simulated sample writes it; a second job configured by that file
 * alone writes byte-identical trajectories and maps, and the file holds
 * every key of the INI the first job was given (the [line_extraction_<method>]
 * section was missing before). */
#include "batch_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>
#include <hslam/slam/mapping_config.h>
#include <hslam/testing/temp_dir.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace hslam;

namespace
{
const std::string kSample = std::string(HSLAM_SOURCE_DIR) + "/rawlog_samples/floor/sim.rawlog";

std::string fileBytes(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	std::stringstream bytes;
	bytes << in.rdbuf();
	return bytes.str();
}

batch::TBatchResult runWith(const std::string& ini, const std::vector<std::string>& overrides, const std::string& out)
{
	batch::TBatchRequest request;
	request.config_file = ini;
	request.overrides = overrides;
	request.input_rawlog = kSample;
	request.output_dir = out;
	request.show_progress = false;
	std::ostringstream stdoutText, stderrText;
	return batch::CBatchProcessor(request, stdoutText, stderrText).run();
}

/** Same value: equal numbers (0.10 = 0.1) or equal text. */
bool sameValue(const std::string& a, const std::string& b)
{
	const auto x = common::tryParseDouble(a), y = common::tryParseDouble(b);
	if (x && y) return *x == *y;
	const auto bx = common::tryParseBool(a), by = common::tryParseBool(b);
	if (bx && by) return *bx == *by;
	return a == b;
}
}  // namespace

TEST(ConfigRoundTrip, RerunFromConfigUsedIniGivesIdenticalOutputs)
{
	hslam::testing::CTempDir dir;
	// Non-default values in sections the run reads, among them the line
	// extractor's and a key in degrees, so a gap in config_used.ini shows.
	const std::vector<std::string> overrides{"line_extraction_derivative.min_points=6",
											 "pose_estimation.match_every_deg=7.3", "ukf.gate_nis=40",
											 "grid.resolution_m=0.07", "output.write_tiles=false"};
	const auto first = runWith(slam::testing::kDefaultIni, overrides, dir.file("a"));
	ASSERT_TRUE(first.input_error.empty()) << first.input_error;
	ASSERT_GT(first.counters.laser_scans, 100u);
	const auto second = runWith(dir.file("a/config_used.ini"), {}, dir.file("b"));
	EXPECT_EQ(second.counters.laser_scans, first.counters.laser_scans);

	for (const char* name : {"trajectory.tum", "odometry.tum", "pose_estimates.csv", "map.png", "map.gridmap.gz",
							 "tracks.csv", "map_sonar_only.png", "sonar_corners.csv", "config_used.ini"})
	{
		const std::string a = fileBytes(dir.file(std::string("a/") + name)), b = fileBytes(dir.file(std::string("b/") + name));
		EXPECT_GT(a.size(), 0u) << name;
		EXPECT_TRUE(a == b) << name << " differs between the run and its rerun from config_used.ini";
	}
}

TEST(ConfigRoundTrip, ConfigUsedIniHoldsEveryKeyOfTheGivenIni)
{
	// Every key hslam-default.ini sets, in every section the run reads (all
	// but the line extractors not chosen), is in config_used.ini with the
	// same value.
	hslam::testing::CTempDir dir;
	ASSERT_TRUE(runWith(slam::testing::kDefaultIni, {}, dir.file("a")).input_error.empty());
	const auto given = common::loadIniFile(slam::testing::kDefaultIni);
	const auto used = common::loadIniFile(dir.file("a/config_used.ini"));
	const std::string method = common::trim(given.read_string("line_extraction", "method", "derivative"));
	std::vector<std::string> sections;
	given.getAllSections(sections);
	size_t compared = 0, extractorKeys = 0;
	for (const auto& section : sections)
	{
		if (section.rfind("line_extraction_", 0) == 0 && section != "line_extraction_" + method) continue;
		std::vector<std::string> keys;
		given.getAllKeys(section, keys);
		for (const auto& key : keys)
		{
			ASSERT_TRUE(used.keyExists(section, key)) << "[" << section << "] " << key << " missing in config_used.ini";
			const std::string a = common::stripInlineComment(given.read_string(section, key, "", false));
			const std::string b = common::stripInlineComment(used.read_string(section, key, "", false));
			EXPECT_TRUE(sameValue(a, b)) << "[" << section << "] " << key << ": '" << a << "' vs '" << b << "'";
			++compared;
			extractorKeys += section == "line_extraction_" + method;
		}
	}
	EXPECT_EQ(extractorKeys, 11u);  // the 11 keys hslam-default.ini sets for the derivative extractor
	EXPECT_GT(compared, 100u);
}

TEST(ConfigRoundTrip, PathsInConfigUsedIniAreAbsolute)
{
	// classifier_model written relative to its INI (config_ini/hslam-legs-hokuyo.ini)
	// becomes absolute, so config_used.ini works from any folder.
	const auto config =
		slam::TMappingConfig::fromConfig(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-legs-hokuyo.ini", {});
	EXPECT_EQ(common::trim(config.ini.read_string("dynamic_objects", "classifier_model", "")),
			  std::string(HSLAM_SOURCE_DIR) + "/config_ini/models/legs-hokuyo-forest.yml.gz");
}

TEST(ConfigRoundTrip, UnreadSectionsAreCheckedToo)
{
	// A typo in a section the chosen method does not read is still an error.
	EXPECT_THROW(slam::TMappingConfig::fromConfig("", {"line_extraction_iep.min_pionts=5"}), common::config_error);
	EXPECT_THROW(slam::TMappingConfig::fromConfig("", {"pose_estimation.method=odometry", "ukf.gate_nsi=3"}),
				 common::config_error);
	EXPECT_NO_THROW(slam::TMappingConfig::fromConfig("", {"line_extraction_iep.min_points=5"}));
}

TEST(ConfigRoundTrip, AKeyLeftOutTakesTheShippedDefault)
{
	// An INI that leaves keys out (here: no INI at all) runs with
	// config_ini/hslam-default.ini's values, not with other defaults in code:
	// the two runs record the same configuration and the same trajectory.
	hslam::testing::CTempDir dir;
	ASSERT_TRUE(runWith(slam::testing::kDefaultIni, {"output.write_tiles=false"}, dir.file("a")).input_error.empty());
	ASSERT_TRUE(runWith("", {"output.write_tiles=false"}, dir.file("b")).input_error.empty());
	const auto shipped = common::loadIniFile(dir.file("a/config_used.ini"));
	const auto bare = common::loadIniFile(dir.file("b/config_used.ini"));
	std::vector<std::string> sections;
	shipped.getAllSections(sections);
	size_t compared = 0;
	for (const auto& section : sections)
	{
		std::vector<std::string> keys;
		shipped.getAllKeys(section, keys);
		for (const auto& key : keys)
		{
			const std::string a = common::stripInlineComment(shipped.read_string(section, key, "", false));
			const std::string b = common::stripInlineComment(bare.read_string(section, key, "<missing>", false));
			EXPECT_TRUE(sameValue(a, b)) << "[" << section << "] " << key << ": shipped '" << a << "', left out '" << b
										 << "'";
			++compared;
		}
	}
	EXPECT_GT(compared, 300u);
	EXPECT_EQ(fileBytes(dir.file("a/trajectory.tum")), fileBytes(dir.file("b/trajectory.tum")));
}
