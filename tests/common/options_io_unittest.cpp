#include <gtest/gtest.h>
#include <hslam/common/config_overrides.h>
#include <hslam/common/options_io.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

using hslam::common::config_error;

namespace
{
struct TExampleOptions
{
	double range_m = 3.0;
	int cells = 200;
	bool enabled = false;
	std::string method = "odometry";
	double cone_rad = 0.5;

	template <class V>
	void visit(V& v)
	{
		v.real("range_m", range_m, 0.0, 80.0);
		v.integer("cells", cells, 10, 1000);
		v.flag("enabled", enabled);
		v.choice("method", method, {"odometry", "lines"});
		v.degrees("cone_deg", cone_rad, 1.0, 90.0);
	}
};

TExampleOptions loadFrom(const std::string& ini)
{
	mrpt::config::CConfigFileMemory cfg(ini);
	TExampleOptions o;
	hslam::common::loadOptions(o, cfg, "s");
	return o;
}
}  // namespace

TEST(OptionsIo, AbsentKeysKeepDefaults)
{
	const auto o = loadFrom("[other]\nx=1\n");
	EXPECT_DOUBLE_EQ(o.range_m, 3.0);
	EXPECT_EQ(o.cells, 200);
	EXPECT_EQ(o.method, "odometry");
}

TEST(OptionsIo, AnAbsentAngleKeepsItsRadiansBitForBit)
{
	// Degrees and back move a third of these by an ulp (300 deg/s became
	// 300.00000000000006 in config_used.ini); a key left out must not.
	for (int i = 1; i < 115; ++i)
	{
		mrpt::config::CConfigFileMemory cfg("[s]\nrange_m = 1\n");
		TExampleOptions o;
		o.cone_rad = i * 0.0137;  // 0.8 .. 89.5 deg
		hslam::common::loadOptions(o, cfg, "s");
		EXPECT_EQ(o.cone_rad, i * 0.0137) << i;
	}
}

TEST(OptionsIo, ReadsValuesWithInlineComments)
{
	const auto o = loadFrom("[s]\nrange_m = 4.5 ; metres\ncells = 50 # cells\nenabled = yes\nmethod = lines // c\ncone_deg = 30\n");
	EXPECT_DOUBLE_EQ(o.range_m, 4.5);
	EXPECT_EQ(o.cells, 50);
	EXPECT_TRUE(o.enabled);
	EXPECT_EQ(o.method, "lines");
	EXPECT_NEAR(o.cone_rad, M_PI / 6, 1e-12);
}

TEST(OptionsIo, RejectsOutOfRangeNamingSectionAndKey)
{
	try
	{
		loadFrom("[s]\nrange_m = 100\n");
		FAIL() << "no exception";
	}
	catch (const config_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("[s] range_m"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
	}
}

TEST(OptionsIo, RejectsGarbageNumbersAndUnknownChoices)
{
	EXPECT_THROW(loadFrom("[s]\nrange_m = 3m\n"), config_error);
	EXPECT_THROW(loadFrom("[s]\ncells = 2.5\n"), config_error);
	EXPECT_THROW(loadFrom("[s]\nenabled = maybe\n"), config_error);
	EXPECT_THROW(loadFrom("[s]\nmethod = magic\n"), config_error);
	EXPECT_THROW(loadFrom("[s]\nrange_m = nan\n"), config_error);
}

TEST(OptionsIo, RejectsUnknownKeys)
{
	try
	{
		loadFrom("[s]\nrange_m = 1\nrnage_m = 2\n");
		FAIL() << "no exception";
	}
	catch (const config_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("rnage_m"), std::string::npos) << e.what();
	}
}

TEST(OptionsIo, SaveThenLoadRoundTrips)
{
	TExampleOptions original;
	original.range_m = 7.25;
	original.cells = 321;
	original.enabled = true;
	original.method = "lines";
	original.cone_rad = 0.3;
	mrpt::config::CConfigFileMemory cfg;
	hslam::common::saveOptions(original, cfg, "s");
	TExampleOptions loaded;
	hslam::common::loadOptions(loaded, cfg, "s");
	EXPECT_DOUBLE_EQ(loaded.range_m, 7.25);
	EXPECT_EQ(loaded.cells, 321);
	EXPECT_TRUE(loaded.enabled);
	EXPECT_EQ(loaded.method, "lines");
	EXPECT_NEAR(loaded.cone_rad, 0.3, 1e-9);
}

TEST(ConfigOverrides, ParsesAndApplies)
{
	const auto o = hslam::common::parseConfigOverride("grid.max_range_m=5.5");
	EXPECT_EQ(o.section, "grid");
	EXPECT_EQ(o.key, "max_range_m");
	EXPECT_EQ(o.value, "5.5");
	EXPECT_THROW(hslam::common::parseConfigOverride("grid_max_range=5"), config_error);
	EXPECT_THROW(hslam::common::parseConfigOverride("grid.=5"), config_error);
	EXPECT_THROW(hslam::common::loadConfigWithOverrides("/nonexistent/file.ini", {}), config_error);
	const auto cfg = hslam::common::loadConfigWithOverrides("", {"a.b=1", "a.b=2"});
	EXPECT_EQ(cfg.read_string("a", "b", ""), "2");
}

TEST(ConfigOverrides, UnknownSectionsAreReported)
{
	mrpt::config::CConfigFileMemory cfg(std::string("[grid]\na=1\n[gird]\nb=2\n"));
	EXPECT_THROW(hslam::common::checkKnownSections(cfg, {"grid"}), config_error);
	EXPECT_NO_THROW(hslam::common::checkKnownSections(cfg, {"grid", "gird"}));
}
