/* hslam tests: malformed INI files given to the real apps. Each is refused
 * with exit code 1 and a message naming the file and the line, before any
 * output is created (MRPT alone would read them as empty or partial
 * configurations and run with defaults). */
#include <gtest/gtest.h>
#include <hslam/testing/temp_dir.h>
#include <hslam/testing/test_paths.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
const std::string kSource = HSLAM_SOURCE_DIR;
const std::string kBin = HSLAM_BIN_DIR;

std::string readText(const std::string& path) { return hslam::testing::readTextFile(path); }

void writeFile(const std::string& path, const std::string& bytes)
{
	std::ofstream(path, std::ios::binary) << bytes;
}

/** Runs `command` from the repository root, stderr into `errFile`. */
int run(const std::string& command, const std::string& errFile)
{
	return hslam::testing::runCommand("cd '" + kSource + "' && " + command + " > /dev/null 2> '" + errFile + "'");
}

struct TBadIni
{
	const char* name;
	std::string bytes;
	std::string message;  //!< expected after "FILE:"
};

std::vector<TBadIni> badInis()
{
	return {
		{"binary", std::string("[grid]\nresolution_m = 0.1\n\x1f\x8b\x08\0\0", 31),
		 "3: not an INI text file (control byte 0x1f at column 1)"},
		{"key_before_section", "resolution_m = 0.1\n[grid]\n", "1: key 'resolution_m' comes before any [section]"},
		{"no_equals", "[grid]\nresolution_m 0.1\n",
		 "2: 'resolution_m 0.1' is neither '[section]' nor 'key = value' nor a comment (; # //)"},
		{"repeated_key", "[grid]\nresolution_m = 0.1\nresolution_m = 0.05\n",
		 "3: key 'resolution_m' appears again in [grid] (first at line 2)"},
		{"repeated_section", "[grid]\nresolution_m = 0.1\n[laser_model]\n[grid]\n",
		 "4: section [grid] appears again (first at line 1); merge the two into one"},
		{"misspelt_section", "[grid]\nresolution_m = 0.1\n\n[laser_modle]\nmax_range_m = 5\n",
		 "4: unknown section [laser_modle] (known sections: process, grid, laser_model"},
	};
}
}  // namespace

TEST(ConfigApps, HslamProcessRefusesEachMalformedIni)
{
	hslam::testing::CTempDir dir;
	for (const auto& bad : badInis())
	{
		const std::string ini = dir.file(std::string(bad.name) + ".ini"), out = dir.file(std::string(bad.name) + "_out");
		writeFile(ini, bad.bytes);
		const int rc = run(kBin + "/hslam-process -q -c '" + ini + "' -i rawlog_samples/floor/sim.rawlog -o '" + out + "'",
						   dir.file("err.txt"));
		const std::string err = readText(dir.file("err.txt"));
		EXPECT_EQ(rc, 1) << bad.name << ": " << err;
		EXPECT_NE(err.find("hslam-process: error: " + ini + ":" + bad.message), std::string::npos) << bad.name << ": " << err;
		EXPECT_FALSE(std::filesystem::exists(out)) << bad.name << ": output written despite the bad configuration";
	}
}

TEST(ConfigApps, GrabberRejectsAMisspeltMapConfigSection)
{
	// The grabber INI is good (the Pioneer + LMS200 recording set-up); the
	// pipeline INI of --map-config has [laser_modle]. The grabber stops
	// before opening any device or creating the rawlog.
	hslam::testing::CTempDir dir;
	const TBadIni bad = badInis().back();
	writeFile(dir.file("map.ini"), bad.bytes);
	const int rc = run(kBin + "/hslam-grabber config_ini/grabber-pioneer-lms200.ini -o '" + dir.file("rec.rawlog") +
						   "' --duration 1 --map-out '" + dir.file("map") + "' --map-config '" + dir.file("map.ini") + "'",
					   dir.file("err.txt"));
	const std::string err = readText(dir.file("err.txt"));
	EXPECT_EQ(rc, 1) << err;
	EXPECT_NE(err.find("hslam-grabber: " + dir.file("map.ini") + ":" + bad.message), std::string::npos) << err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("rec.rawlog")));
	EXPECT_FALSE(std::filesystem::exists(dir.file("map")));
}

TEST(ConfigApps, GrabberMapConfigGoesThroughTheSameChecksAsHslamProcess)
{
	// A repeated key in --map-config and a binary grabber INI: both named by file and line.
	hslam::testing::CTempDir dir;
	const TBadIni repeated = badInis()[3];
	writeFile(dir.file("map.ini"), repeated.bytes);
	int rc = run(kBin + "/hslam-grabber config_ini/grabber-pioneer-lms200.ini -o '" + dir.file("rec.rawlog") +
					 "' --map-out '" + dir.file("map") + "' --map-config '" + dir.file("map.ini") + "'",
				 dir.file("err.txt"));
	EXPECT_EQ(rc, 1);
	EXPECT_NE(readText(dir.file("err.txt")).find(dir.file("map.ini") + ":" + repeated.message), std::string::npos)
		<< readText(dir.file("err.txt"));
	const TBadIni binary = badInis()[0];
	writeFile(dir.file("grab.ini"), binary.bytes);
	rc = run(kBin + "/hslam-grabber '" + dir.file("grab.ini") + "' -o '" + dir.file("rec.rawlog") + "'",
			 dir.file("err.txt"));
	EXPECT_EQ(rc, 1);
	EXPECT_NE(readText(dir.file("err.txt")).find(dir.file("grab.ini") + ":" + binary.message), std::string::npos)
		<< readText(dir.file("err.txt"));
	EXPECT_FALSE(std::filesystem::exists(dir.file("rec.rawlog")));
}

TEST(ConfigApps, OtherAppsReadIniFilesThroughTheSameReader)
{
	hslam::testing::CTempDir dir;
	const TBadIni bad = badInis()[1];  // key before any section
	writeFile(dir.file("bad.ini"), bad.bytes);
	const std::string expected = dir.file("bad.ini") + ":" + bad.message;
	const std::vector<std::pair<std::string, std::string>> commands{
		{"hslam-simulate", kBin + "/hslam-simulate -q -c '" + dir.file("bad.ini") + "' -o '" + dir.file("sim") + "'"},
		{"hslam-bench", kBin + "/hslam-bench legs-sim -c '" + dir.file("bad.ini") + "' --out '" + dir.file("b") + "'"},
		{"hslam-legs-train", kBin + "/hslam-legs-train -c '" + dir.file("bad.ini") + "' -o '" + dir.file("m.yml") + "'"},
	};
	for (const auto& [app, command] : commands)
	{
		EXPECT_EQ(run(command, dir.file("err.txt")), 1) << app;
		const std::string err = readText(dir.file("err.txt"));
		EXPECT_NE(err.find(expected), std::string::npos) << app << ": " << err;
	}
	EXPECT_FALSE(std::filesystem::exists(dir.file("sim")));
	EXPECT_FALSE(std::filesystem::exists(dir.file("m.yml")));
}

TEST(ConfigApps, BenchChecksItsOverridesBeforeAnyRun)
{
	// hslam-bench pipeline / graph --set: a bad override fails at once with
	// hslam-process's own message, before any run (the suites take minutes).
	hslam::testing::CTempDir dir;
	const std::string lab = kSource + "/rawlog_samples/lab/sim.rawlog";
	const std::vector<std::pair<std::string, std::string>> cases{
		{"--set icp.nonsense=1", "[icp] unknown key(s): nonsense"},
		{"--set icp.restart_below_fit=2", "[icp] restart_below_fit = '2': out of range [0, 1]"},
		{"--set icp.restart_below_fit", "--set 'icp.restart_below_fit': expected SECTION.KEY=VALUE"},
	};
	for (const auto& [set, message] : cases)
		for (const std::string suite : {"pipeline", "graph --max-keyframes 500"})
		{
			const std::string out = dir.file("out");
			EXPECT_EQ(run(kBin + "/hslam-bench " + suite + " -r '" + lab + "' " + set + " --out '" + out + "'",
						  dir.file("err.txt")),
					  1)
				<< suite << " " << set;
			const std::string err = readText(dir.file("err.txt"));
			EXPECT_NE(err.find(message), std::string::npos) << suite << " " << set << ": " << err;
			EXPECT_FALSE(std::filesystem::exists(out + "/lab")) << suite << " " << set;  // nothing was run
		}
}

TEST(ConfigApps, BenchPassesItsOverridesToEveryRun)
{
	// The overrides reach the timed runs (the full run and the one-scan
	// prefix that start-up is measured on).
	hslam::testing::CTempDir dir;
	const std::string lab = dir.file("lab.rawlog");  // the lab sample's first 300 entries (a few seconds)
	ASSERT_EQ(run("rawlog-edit --cut --from-index 0 --to-index 300 -q -i '" + kSource +
					  "/rawlog_samples/lab/sim.rawlog' -o '" + lab + "'",
				  dir.file("err.txt")),
			  0);
	ASSERT_EQ(run(kBin + "/hslam-bench pipeline -r '" + lab + "' -g - -n 1 --set pose_estimation.method=odometry --set " +
					  "loop_closure.enabled=false --out '" + dir.file("out") + "'",
				  dir.file("err.txt")),
			  0)
		<< readText(dir.file("err.txt"));
	for (const char* run : {"hslam", "hslam-prefix"})
	{
		const std::string used = readText(dir.file("out") + "/lab/" + run + "/config_used.ini");
		EXPECT_NE(used.find("method = odometry"), std::string::npos) << run;
	}
	EXPECT_NE(readText(dir.file("out") + "/lab/hslam/config_used.ini").find("[loop_closure]\nenabled = false"),
			  std::string::npos);
}

TEST(ConfigApps, BenchPrintsOurKeyframesAndTheirCost)
{
	// The keyframes are the back-end's (summary.json), and the cost per
	// keyframe is the same CPU as the cost per scan, divided differently.
	hslam::testing::CTempDir dir;
	const std::string lab = dir.file("lab.rawlog");
	ASSERT_EQ(run("rawlog-edit --cut --from-index 0 --to-index 600 -q -i '" + kSource +
					  "/rawlog_samples/lab/sim.rawlog' -o '" + lab + "'",
				  dir.file("err.txt")),
			  0);
	ASSERT_EQ(hslam::testing::runCommand("cd '" + kSource + "' && " + kBin + "/hslam-bench pipeline -r '" + lab +
										 "' -g - -n 1 --set pose_estimation.method=odometry --out '" +
										 dir.file("out") + "' > '" + dir.file("keys.txt") + "' 2> '" +
										 dir.file("err.txt") + "'"),
			  0)
		<< readText(dir.file("err.txt"));
	const std::string keys = readText(dir.file("keys.txt"));
	const auto value = [&](const std::string& key)
	{
		const size_t at = keys.find("\n" + key + "=");
		return at == std::string::npos ? -1.0 : std::stod(keys.substr(at + key.size() + 2));
	};
	const std::string summary = readText(dir.file("out") + "/lab/hslam/summary.json");
	const size_t at = summary.find("\"keyframes\": ");
	ASSERT_NE(at, std::string::npos);
	const double keyframes = std::stod(summary.substr(at + 13));
	EXPECT_GT(keyframes, 2.0);
	EXPECT_EQ(value("pipeline_lab_keyframes"), keyframes);
	// summary.json counts the scans too
	const size_t scansAt = summary.find("\"scans\": ");
	ASSERT_NE(scansAt, std::string::npos);
	const double scans = std::stod(summary.substr(scansAt + 9));
	EXPECT_NEAR(value("pipeline_lab_pipeline_ms_per_keyframe"),
				value("pipeline_lab_pipeline_ms_per_scan") * (scans - 1) / keyframes,
				1e-3 * value("pipeline_lab_pipeline_ms_per_keyframe"));
}
