#include <gtest/gtest.h>
#include <hslam/common/CProgressBar.h>
#include <hslam/common/CStageTimer.h>

#include <sstream>

TEST(StageTimer, MeanP95MaxFromKnownSamples)
{
	hslam::common::CStageTimer timer;
	for (int i = 1; i <= 100; ++i) timer.add("insert", i * 1e-3);  // 1..100 ms
	timer.add("read", 0.5);
	const auto stats = timer.stats();
	ASSERT_EQ(stats.size(), 2u);
	EXPECT_EQ(stats[0].stage, "insert");  // first-use order
	EXPECT_EQ(stats[0].count, 100u);
	EXPECT_NEAR(stats[0].mean_ms, 50.5, 1e-9);
	EXPECT_NEAR(stats[0].p95_ms, 95.0, 1e-9);
	EXPECT_NEAR(stats[0].max_ms, 100.0, 1e-9);
	EXPECT_NEAR(stats[1].total_ms, 500.0, 1e-9);
	std::ostringstream csv;
	timer.writeCsv(csv);
	EXPECT_NE(csv.str().find("insert,100,50.5,95,100"), std::string::npos) << csv.str();
}

TEST(ProgressBar, NonTerminalPrintsAtMostOneLinePerDecile)
{
	std::ostringstream os;
	hslam::common::CProgressBar bar(os, false, 1000, "scans");
	for (size_t i = 0; i <= 1000; ++i) bar.update(i);
	bar.finish();
	size_t lines = 0;
	for (char c : os.str()) lines += (c == '\n');
	EXPECT_EQ(lines, 11u);  // 0 %, 10 % ... 90 %, and the final line
	EXPECT_NE(os.str().find("1000/1000"), std::string::npos);
}
