/* COutputFolder and the output path guards (issue 15, items 3 and 5): lock,
 * refusal of a foreign non-empty folder, removal of our own stale outputs,
 * atomic writes, output-over-input refusal, printable names. */
#include <gtest/gtest.h>
#include <hslam/common/output_folder.h>
#include <hslam/common/output_paths.h>
#include <hslam/testing/temp_dir.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

using namespace hslam::common;
namespace fs = std::filesystem;

namespace
{
void touch(const std::string& path, const std::string& text = "x")
{
	fs::create_directories(fs::path(path).parent_path());
	std::ofstream(path) << text;
}
}  // namespace

TEST(OutputFolder, SecondRunIntoTheSameFolderIsRefusedWhileTheFirstHoldsIt)
{
	hslam::testing::CTempDir tmp;
	const std::string dir = tmp.file("out");
	COutputFolder first(dir, false);
	// flock is per open file description: a second process (or object) is refused.
	const pid_t pid = fork();
	if (pid == 0)
	{
		try
		{
			COutputFolder second(dir, false);
			_exit(0);
		}
		catch (const output_folder_error& e)
		{
			_exit(std::string(e.what()).find("is in use by another run") != std::string::npos ? 7 : 1);
		}
	}
	int status = 0;
	waitpid(pid, &status, 0);
	EXPECT_EQ(WEXITSTATUS(status), 7);
	EXPECT_THROW(COutputFolder(dir, false), output_folder_error);
}

TEST(OutputFolder, ForeignNonEmptyFolderIsRefusedUnlessOverwrite)
{
	hslam::testing::CTempDir tmp;
	touch(tmp.file("mine/thesis.tex"), "precious");
	try
	{
		COutputFolder f(tmp.file("mine"), false);
		ADD_FAILURE() << "a foreign folder was accepted";
	}
	catch (const output_folder_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("is not empty and was not written by hslam"), std::string::npos) << e.what();
	}
	{
		COutputFolder f(tmp.file("mine"), true);
		f.finish();
	}
	EXPECT_EQ(std::ifstream(tmp.file("mine/thesis.tex")).get(), 'p');  // --overwrite never deletes foreign files
	{
		COutputFolder again(tmp.file("mine"), false);  // ours now (manifest), and the foreign file is not in it
		EXPECT_TRUE(again.staleRemoved().empty());
	}
	EXPECT_TRUE(fs::exists(tmp.file("mine/thesis.tex")));
	EXPECT_NO_THROW(COutputFolder(tmp.file("empty"), false));
}

TEST(OutputFolder, StaleOutputsOfThePreviousRunAreRemoved)
{
	hslam::testing::CTempDir tmp;
	const std::string dir = tmp.file("run");
	{
		COutputFolder f(dir, false);
		touch(dir + "/map.png");
		touch(dir + "/tiles/tile_3_4.png");
		touch(dir + "/frames/frame_000010.png");
		touch(dir + "/evaluation.json", "{\"ate\": 0.8}");
		f.finish();
	}
	touch(dir + "/notes.txt");  // put there by the user after the run
	{
		COutputFolder f(dir, false);  // ours: accepted, the old outputs go
		EXPECT_EQ(f.staleRemoved().size(), 4u);
		EXPECT_FALSE(fs::exists(dir + "/evaluation.json"));
		EXPECT_FALSE(fs::exists(dir + "/tiles"));
		EXPECT_FALSE(fs::exists(dir + "/frames"));
		EXPECT_TRUE(fs::exists(dir + "/notes.txt"));
		touch(dir + "/map.png");
		f.finish();
	}
	// A manifest cannot make the next run delete outside the folder.
	touch(tmp.file("outside.txt"));
	std::ofstream(dir + "/" + COutputFolder::MANIFEST_NAME) << "../outside.txt\n" << tmp.file("outside.txt") << "\n";
	COutputFolder f(dir, false);
	EXPECT_TRUE(fs::exists(tmp.file("outside.txt")));
}

TEST(OutputFolder, AtomicWriteLeavesThePreviousFileWhenTheWriterFails)
{
	hslam::testing::CTempDir tmp;
	const std::string path = tmp.file("summary.csv");
	writeTextFileAtomically(path, "v1\n");
	try
	{
		writeFileAtomically(path, [](const std::string& t) {
			std::ofstream(t) << "half";
			throw std::runtime_error("No space left on device");
		});
		ADD_FAILURE();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("summary.csv: write failed or cut short"), std::string::npos) << e.what();
		EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos);
	}
	std::ifstream in(path);
	std::string line;
	std::getline(in, line);
	EXPECT_EQ(line, "v1");
	EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path()), fs::directory_iterator()), 1);  // no temporary left
	if (fs::exists("/dev/full"))  // a real full disk: every write fails
	{
		EXPECT_THROW(writeFileAtomically(path, [](const std::string&) { writeTextFileAtomically("/dev/full", "data"); }),
					 std::runtime_error);
	}
}

TEST(OutputPaths, OutputOverInputIsRefusedThroughLinksAndDots)
{
	hslam::testing::CTempDir tmp;
	touch(tmp.file("in.log"));
	fs::create_symlink(tmp.file("in.log"), tmp.file("link.log"));
	fs::create_hard_link(tmp.file("in.log"), tmp.file("hard.log"));
	for (const auto& out : {tmp.file("in.log"), tmp.file("link.log"), tmp.file("hard.log"), tmp.path().string() + "/./in.log"})
		EXPECT_THROW(refuseOutputOverInput(out, "output", {tmp.file("other"), tmp.file("in.log")}), output_path_error) << out;
	EXPECT_NO_THROW(refuseOutputOverInput(tmp.file("new.rawlog"), "output", {tmp.file("in.log")}));
	EXPECT_EQ(printableName("a\x1b[31mred\x07.log"), "a?[31mred?.log");
}
