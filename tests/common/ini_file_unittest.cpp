/* hslam tests: the strict INI reader (ini_file.h) on hand-written files:
 * each malformed case is refused with the file and line, and what MRPT
 * accepts as good INI reads the same as through MRPT itself. */
#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/ini_file.h>
#include <hslam/common/options_io.h>
#include <hslam/common/parse_number.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>

#include <filesystem>
#include <fstream>

using hslam::common::config_error;
using hslam::common::loadIniFile;
using hslam::common::parseIniText;

namespace
{
/** The message parseIniText throws for `text` ("" if it accepts it). */
std::string errorOf(const std::string& text)
{
	try
	{
		parseIniText(text, "t.ini");
	}
	catch (const config_error& e)
	{
		return e.what();
	}
	return "";
}

void writeFile(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary) << bytes;
}
}  // namespace

TEST(IniFile, ReadsMrptConventions)
{
	const auto cfg = parseIniText(
		"; comment\n# comment\n// comment = not a key\n[grid]  ; trailing comment\n"
		"resolution_m = 0.05\n  tile_size_cells=100 // inline\n@define R 2\n[laser_model]\nmax_range_m = ${R}\n"
		"long = 1 \\\n 2\n",
		"t.ini");
	EXPECT_EQ(cfg.read_double("grid", "resolution_m", 0), 0.05);
	EXPECT_EQ(cfg.read_int("grid", "tile_size_cells", 0), 100);
	EXPECT_EQ(cfg.read_int("laser_model", "max_range_m", 0), 2);
	EXPECT_EQ(hslam::common::trim(cfg.read_string("laser_model", "long", "")), "1  2");
	std::vector<std::string> keys;
	cfg.getAllKeys("grid", keys);
	EXPECT_EQ(keys.size(), 2u);  // "// comment" did not become a key
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	EXPECT_EQ(sections, (std::vector<std::string>{"grid", "laser_model"}));
}

TEST(IniFile, BinaryFileIsRefusedWithLineAndColumn)
{
	EXPECT_EQ(errorOf("[a]\nx = 1\n\x1f\x8b\x08"), "t.ini:3: not an INI text file (control byte 0x1f at column 1)");
	EXPECT_EQ(errorOf(std::string("[a]\nx = 1\0", 10)), "t.ini:2: not an INI text file (control byte 0x00 at column 6)");
}

TEST(IniFile, KeyBeforeAnySectionIsRefused)
{
	EXPECT_EQ(errorOf("; header\nresolution_m = 0.1\n[grid]\n"), "t.ini:2: key 'resolution_m' comes before any [section]");
}

TEST(IniFile, LineWithoutEqualsIsRefused)
{
	EXPECT_EQ(errorOf("[grid]\nresolution_m 0.1\n"),
			  "t.ini:2: 'resolution_m 0.1' is neither '[section]' nor 'key = value' nor a comment (; # //)");
	EXPECT_EQ(errorOf("[grid]\n= 0.1\n"), "t.ini:2: '= 0.1' has no key before '='");
}

TEST(IniFile, RepeatedKeyIsRefused)
{
	EXPECT_EQ(errorOf("[grid]\na = 1\n\nA = 2\n"), "t.ini:4: key 'A' appears again in [grid] (first at line 2)");
	EXPECT_EQ(errorOf("[grid]\na = 1\n[laser_model]\na = 2\n"), "");  // same key, other section: fine
}

TEST(IniFile, RepeatedSectionIsRefused)
{
	EXPECT_EQ(errorOf("[grid]\na = 1\n[icp]\n[Grid]\nb = 2\n"),
			  "t.ini:4: section [Grid] appears again (first at line 1); merge the two into one");
}

TEST(IniFile, MalformedSectionHeadersAreRefused)
{
	EXPECT_EQ(errorOf("[grid\n"), "t.ini:1: section header '[grid' has no closing ']'");
	EXPECT_EQ(errorOf("[ ]\n"), "t.ini:1: empty section name '[ ]'");
	EXPECT_EQ(errorOf("[grid] x = 1\n"), "t.ini:1: text after the section header '[grid] x = 1'");
}

TEST(IniFile, LineNumbersCountContinuedLines)
{
	EXPECT_EQ(errorOf("[a]\nx = 1 \\\n  2\nbad\n"),
			  "t.ini:4: 'bad' is neither '[section]' nor 'key = value' nor a comment (; # //)");
}

TEST(IniFile, FilesAreNamedInErrors)
{
	hslam::testing::CTempDir dir;
	EXPECT_THROW(loadIniFile(dir.file("missing.ini")), config_error);
	try
	{
		loadIniFile(dir.path().string());
		FAIL();
	}
	catch (const config_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("is a folder"), std::string::npos) << e.what();
	}
	writeFile(dir.file("bin.ini"), std::string("\x89PNG\r\n\x1a\n", 8));
	try
	{
		loadIniFile(dir.file("bin.ini"));
		FAIL();
	}
	catch (const config_error& e)
	{
		EXPECT_EQ(std::string(e.what()), dir.file("bin.ini") + ":2: not an INI text file (control byte 0x1a at column 1)");
	}
	writeFile(dir.file("empty.ini"), "");
	std::vector<std::string> sections;
	loadIniFile(dir.file("empty.ini")).getAllSections(sections);
	EXPECT_TRUE(sections.empty());  // an empty file is valid INI: all defaults
}

TEST(IniFile, UnknownSectionIsNamedWithFileAndLine)
{
	hslam::testing::CTempDir dir;
	writeFile(dir.file("a.ini"), "[grid]\na = 1\n\n[gird]\nb = 2\n");
	const auto cfg = loadIniFile(dir.file("a.ini"));
	try
	{
		hslam::common::checkKnownSectionsInFile(cfg, {"grid"}, dir.file("a.ini"));
		FAIL();
	}
	catch (const config_error& e)
	{
		EXPECT_EQ(std::string(e.what()), dir.file("a.ini") + ":4: unknown section [gird] (known sections: grid)");
	}
}

TEST(IniFile, EveryShippedIniReadsAsMrptReadsIt)
{
	// Every file of config_ini/ passes, and gives the same sections, keys
	// and values as MRPT's own CConfigFile.
	size_t files = 0;
	for (const auto& entry : std::filesystem::directory_iterator(std::string(HSLAM_SOURCE_DIR) + "/config_ini"))
	{
		if (entry.path().extension() != ".ini") continue;
		++files;
		const auto ours = loadIniFile(entry.path().string());
		const mrpt::config::CConfigFile mrpts(entry.path().string());
		std::vector<std::string> sections, mrptSections;
		ours.getAllSections(sections);
		mrpts.getAllSections(mrptSections);
		EXPECT_EQ(sections, mrptSections) << entry.path();
		for (const auto& section : sections)
		{
			std::vector<std::string> keys;
			ours.getAllKeys(section, keys);
			for (const auto& key : keys)
				EXPECT_EQ(ours.read_string(section, key, "?"), mrpts.read_string(section, key, "!"))
					<< entry.path() << " [" << section << "] " << key;
		}
	}
	EXPECT_GE(files, 10u);
}

TEST(ConfigOverrides, PathsAreResolvedNextToTheIniAndOverridesAgainstTheWorkingDirectory)
{
	hslam::testing::CTempDir dir;
	std::filesystem::create_directories(dir.path() / "conf");
	writeFile(dir.file("conf/a.ini"), "[dynamic_objects]\nclassifier_model = models/m.yml.gz ; the model\n");
	const std::vector<hslam::common::TPathKey> paths{{"dynamic_objects", "classifier_model"}};
	const auto cfg = hslam::common::loadConfigWithOverrides(dir.file("conf/a.ini"), {}, paths);
	// Relative to the INI's folder although nothing exists there (never the working directory).
	EXPECT_EQ(cfg.read_string("dynamic_objects", "classifier_model", ""), dir.file("conf/models/m.yml.gz"));
	const auto overridden =
		hslam::common::loadConfigWithOverrides(dir.file("conf/a.ini"), {"dynamic_objects.classifier_model=x.yml"}, paths);
	EXPECT_EQ(overridden.read_string("dynamic_objects", "classifier_model", ""),
			  (std::filesystem::current_path() / "x.yml").string());
	const auto absolute = hslam::common::loadConfigWithOverrides(
		dir.file("conf/a.ini"), {"dynamic_objects.classifier_model=/abs/m.yml"}, paths);
	EXPECT_EQ(absolute.read_string("dynamic_objects", "classifier_model", ""), "/abs/m.yml");
}
