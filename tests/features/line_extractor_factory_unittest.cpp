/* createLineExtractor(): method names, INI options, errors. */
#include "line_test_utils.h"

#include <gtest/gtest.h>
#include <hslam/common/options_io.h>
#include <hslam/features/CDerivativeLineExtractor.h>
#include <hslam/features/CIepLineExtractor.h>
#include <hslam/features/CRansacLineExtractor.h>
#include <hslam/testing/test_paths.h>
#include <mrpt/config/CConfigFile.h>

#include <algorithm>

using namespace hslam::features;
using namespace hslam::benchdata;
using hslam::common::config_error;

namespace
{
std::string errorOf(const std::string& method, const std::string& ini)
{
	const mrpt::config::CConfigFileMemory cfg(ini);
	try
	{
		createLineExtractor(method, cfg, lineExtractorSection(method));
	}
	catch (const config_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(LineExtractorFactory, BuildsEveryMethodByName)
{
	const mrpt::config::CConfigFileMemory empty;
	ASSERT_EQ(lineExtractorMethods(), (std::vector<std::string>{"derivative", "iep", "ransac"}));
	for (const auto& m : lineExtractorMethods())
	{
		const auto ex = createLineExtractor(m, empty, lineExtractorSection(m));
		ASSERT_NE(ex, nullptr);
		EXPECT_EQ(ex->name(), m);
	}
	EXPECT_EQ(lineExtractorSection("iep"), "line_extraction_iep");
}

TEST(LineExtractorFactory, UnknownMethodIsAConfigError)
{
	const std::string what = errorOf("hough", "");
	EXPECT_NE(what.find("hough"), std::string::npos) << what;
	EXPECT_NE(what.find("derivative, iep, ransac"), std::string::npos) << what;
}

TEST(LineExtractorFactory, UnknownKeyNamesSectionAndKey)
{
	const std::string what = errorOf("iep", "[line_extraction_iep]\nsplit_distance_m = 0.1\nsplit_dist = 0.2\n");
	EXPECT_NE(what.find("line_extraction_iep"), std::string::npos) << what;
	EXPECT_NE(what.find("split_dist"), std::string::npos) << what;
	// a key of another method is unknown here too
	EXPECT_NE(errorOf("ransac", "[line_extraction_ransac]\nmerge_angle_deg = 5\n").find("merge_angle_deg"),
			  std::string::npos);
}

TEST(LineExtractorFactory, OutOfRangeAndMalformedValues)
{
	EXPECT_NE(errorOf("derivative", "[line_extraction_derivative]\npeak_threshold = 0\n").find("peak_threshold"),
			  std::string::npos);
	EXPECT_NE(errorOf("derivative", "[line_extraction_derivative]\nmin_points = 1\n").find("min_points"),
			  std::string::npos);
	EXPECT_NE(errorOf("ransac", "[line_extraction_ransac]\ndistance_threshold_m = abc\n").find("distance_threshold_m"),
			  std::string::npos);
	EXPECT_NE(errorOf("iep", "[line_extraction_iep]\nmerge_angle_deg = 90\n").find("merge_angle_deg"),
			  std::string::npos);
}

TEST(LineExtractorFactory, OptionsAreReadWithUnits)
{
	const mrpt::config::CConfigFileMemory cfg(std::string(
		"[line_extraction_derivative]\nmerge_angle_deg = 20\npeak_threshold = 0.2\nderivative_step_deg = 1\n"
		"gap_ratio = 1.1\n"));
	CDerivativeLineExtractor::TOptions o;
	hslam::common::loadOptions(o, cfg, "line_extraction_derivative");
	EXPECT_NEAR(o.merge_angle_rad, 20 * M_PI / 180, 1e-12);
	EXPECT_DOUBLE_EQ(o.peak_threshold, 0.2);
	EXPECT_NEAR(o.derivative_step_rad, M_PI / 180, 1e-12);
	EXPECT_DOUBLE_EQ(o.gap_ratio, 1.1);
}

TEST(LineExtractorFactory, OptionsTakeEffect)
{
	const auto sim = test::simulate(test::boxRoom(0));
	for (const auto& m : lineExtractorMethods())
	{
		const mrpt::config::CConfigFileMemory cfg("[" + lineExtractorSection(m) + "]\nmin_points = 70\n");
		mrpt::random::getRandomGenerator().randomize(7);
		const auto lines = createLineExtractor(m, cfg, lineExtractorSection(m))->extract(sim.scan);
		// only the walls seen by >= 70 beams are left: none (54, 63, 64 beams)
		EXPECT_TRUE(lines.empty()) << m;
		const mrpt::config::CConfigFileMemory cfg2("[" + lineExtractorSection(m) + "]\nmin_points = 60\n");
		EXPECT_EQ(createLineExtractor(m, cfg2, lineExtractorSection(m))->extract(sim.scan).size(), 2u) << m;
	}
}

TEST(LineExtractorFactory, SavedOptionsLoadBackIdentically)
{
	CIepLineExtractor::TOptions o;
	o.split_distance_m = 0.07;
	o.merge_angle_rad = 0.1;
	mrpt::config::CConfigFileMemory cfg;
	hslam::common::saveOptions(o, cfg, "line_extraction_iep");
	CIepLineExtractor::TOptions back;
	hslam::common::loadOptions(back, cfg, "line_extraction_iep");
	EXPECT_DOUBLE_EQ(back.split_distance_m, 0.07);
	EXPECT_NEAR(back.merge_angle_rad, 0.1, 1e-9);
}

TEST(LineExtractorFactory, DocumentedIniListsEveryKeyWithItsDefault)
{
	const mrpt::config::CConfigFile file(std::string(HSLAM_SOURCE_DIR) + "/config_ini/hslam-default.ini");
	EXPECT_EQ(file.read_string("line_extraction", "method", ""), "derivative");
	auto compare = [&](auto defaults, const std::string& section) {
		mrpt::config::CConfigFileMemory saved;
		hslam::common::saveOptions(defaults, saved, section);
		std::vector<std::string> savedKeys, fileKeys;
		saved.getAllKeys(section, savedKeys);
		file.getAllKeys(section, fileKeys);
		std::sort(savedKeys.begin(), savedKeys.end());
		std::sort(fileKeys.begin(), fileKeys.end());
		EXPECT_EQ(savedKeys, fileKeys) << section;
		for (const auto& k : savedKeys)
			EXPECT_NEAR(saved.read_double(section, k, -1), file.read_double(section, k, -2), 1e-9)
				<< "[" << section << "] " << k;
		// and the file loads without error
		EXPECT_NO_THROW(createLineExtractor(section.substr(std::string("line_extraction_").size()), file, section));
	};
	compare(CDerivativeLineExtractor::TOptions(), "line_extraction_derivative");
	compare(CIepLineExtractor::TOptions(), "line_extraction_iep");
	compare(CRansacLineExtractor::TOptions(), "line_extraction_ransac");
}
