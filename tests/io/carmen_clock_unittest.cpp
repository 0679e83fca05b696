/* hslam tests: choice of the scan clock (selectCarmenClock). */
#include <gtest/gtest.h>
#include <hslam/io/carmen_clock.h>

#include <limits>

using namespace hslam::io;

namespace
{
std::vector<TCarmenStamp> stamps(const std::vector<double>& ipc, const std::vector<double>& logger)
{
	std::vector<TCarmenStamp> out;
	for (size_t i = 0; i < ipc.size(); ++i) out.push_back({ipc[i], "h", logger[i]});
	return out;
}
}  // namespace

TEST(CarmenClock, UsesIpcWhenItPasses)
{
	const auto c = selectCarmenClock(stamps({10, 11, 12.5}, {20, 21, 22}), "auto", 1.0);
	EXPECT_EQ(c.name, "ipc");
	EXPECT_EQ(c.t_s, (std::vector<double>{10, 11, 12.5}));
}

TEST(CarmenClock, FallsBackToLoggerThenSynthetic)
{
	// csail: ipc printed as 1.13486e+09 for every scan
	auto c = selectCarmenClock(stamps({1.13486e9, 1.13486e9, 1.13486e9}, {5, 6, 7}), "auto", 1.0);
	EXPECT_EQ(c.name, "logger");
	EXPECT_NE(c.reason.find("not strictly increasing"), std::string::npos) << c.reason;
	EXPECT_EQ(c.t_s, (std::vector<double>{5, 6, 7}));

	c = selectCarmenClock(stamps({0, 0, 0}, {5, 4.29e9, 4.29e9 + 1}), "auto", 0.25);
	EXPECT_EQ(c.name, "synthetic");
	EXPECT_NE(c.reason.find("jumps"), std::string::npos) << c.reason;
	EXPECT_EQ(c.t_s, (std::vector<double>{0, 0.25, 0.5}));
}

TEST(CarmenClock, ProblemsAreDetected)
{
	EXPECT_FALSE(carmenClockProblem({1, 2, 2 + kMaxClockJump_s}).has_value());  // exactly 1 h is fine
	EXPECT_TRUE(carmenClockProblem({1, 2, 2.001 + kMaxClockJump_s}).has_value());
	EXPECT_TRUE(carmenClockProblem({1, 2, 1.9}).has_value());  // backwards (intel)
	EXPECT_TRUE(carmenClockProblem({0, 1, 2}).has_value());
	EXPECT_TRUE(carmenClockProblem({1, std::nan(""), 2}).has_value());
	EXPECT_FALSE(carmenClockProblem({}).has_value());
}

TEST(CarmenClock, ForcedClocksAndBadArguments)
{
	const auto s = stamps({3, 2, 1}, {1, 2, 3});
	const auto ipc = selectCarmenClock(s, "ipc", 1.0);
	EXPECT_EQ(ipc.t_s, (std::vector<double>{3, 2, 1}));
	EXPECT_NE(ipc.reason.find("warning"), std::string::npos);
	EXPECT_EQ(selectCarmenClock(s, "synthetic", 2.0).t_s, (std::vector<double>{0, 2, 4}));
	EXPECT_THROW(selectCarmenClock(s, "gps", 1.0), std::invalid_argument);
	EXPECT_THROW(selectCarmenClock(s, "auto", 0.0), std::invalid_argument);
}

TEST(CarmenClockRepair, FewSmallBackwardStepsAreRepairedNotRejected)
{
	// intel-corrected: 4 backward steps of up to 0.86 s among 910 scans.
	std::vector<double> t;  // 200 scans: up to 2 repairs allowed
	for (int k = 0; k < 200; ++k) t.push_back(100.0 + 3.0 * k);
	t[50] = t[49] - 0.5;  // goes back 0.5 s
	t[120] = t[119];  // repeated
	auto repaired = t;
	EXPECT_EQ(hslam::io::repairSmallBackwardSteps(repaired), 2u);
	EXPECT_NEAR(repaired[50], t[49] + 1e-3, 1e-9);
	EXPECT_NEAR(repaired[120], t[119] + 1e-3, 1e-9);
	EXPECT_DOUBLE_EQ(repaired[51], t[51]);  // later stamps untouched
	EXPECT_FALSE(hslam::io::carmenClockProblem(repaired).has_value());

	auto bigStep = t;
	bigStep[50] = t[49] - 5.0;  // more than kMaxRepairableBackStep_s: left alone
	EXPECT_EQ(hslam::io::repairSmallBackwardSteps(bigStep), 0u);
	EXPECT_TRUE(hslam::io::carmenClockProblem(bigStep).has_value());

	std::vector<double> allEqual(200, 1.13486e9);  // csail: too few digits printed
	EXPECT_EQ(hslam::io::repairSmallBackwardSteps(allEqual), 0u);
	EXPECT_TRUE(hslam::io::carmenClockProblem(allEqual).has_value());
}

TEST(CarmenClockRepair, OneBadStampIsRepairedLocallyNotTheWholeClock)
{
	// Issue 15 item 2: one negative or infinite stamp used to switch the whole
	// log to the synthetic clock. Now it is interpolated and warned about.
	for (double bad : {-1.0, std::numeric_limits<double>::infinity(), 1e308, 0.0})
	{
		std::vector<hslam::io::TCarmenStamp> stamps(300);
		for (size_t k = 0; k < stamps.size(); ++k) stamps[k].ipc_s = stamps[k].logger_s = 1000.0 + 0.2 * k;
		stamps[120].ipc_s = bad;
		stamps[0].ipc_s = bad;  // also at the start
		const auto clock = hslam::io::selectCarmenClock(stamps, "auto", 1.0);
		EXPECT_EQ(clock.name, "ipc") << clock.reason;
		EXPECT_EQ(clock.repairedStamps, 2u);
		EXPECT_NEAR(clock.t_s[120], 1000.0 + 0.2 * 120, 1e-9);
		EXPECT_NEAR(clock.t_s[0], 1000.0, 1e-9);
		EXPECT_NE(clock.reason.find("isolated bad stamp"), std::string::npos) << clock.reason;
	}
	// Many bad stamps: not repaired, the clock is rejected as before.
	std::vector<hslam::io::TCarmenStamp> many(300);
	for (size_t k = 0; k < many.size(); ++k) many[k].ipc_s = many[k].logger_s = 1000.0 + 0.2 * k;
	for (size_t k = 10; k < 300; k += 20) many[k].ipc_s = many[k].logger_s = -1;
	EXPECT_EQ(hslam::io::selectCarmenClock(many, "auto", 1.0).name, "synthetic");
}
