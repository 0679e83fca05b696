/* common::CTaskPool: every index runs exactly once, on several threads when
 * the pool has them; the lowest-index error is rethrown; the pool is reusable. */
#include <gtest/gtest.h>
#include <hslam/common/CTaskPool.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using hslam::common::CTaskPool;

TEST(TaskPool, RunsEveryIndexOnceAndIsReusable)
{
	CTaskPool pool(3);
	EXPECT_EQ(pool.threads(), 3u);
	for (size_t count : {0u, 1u, 2u, 7u, 100u})
	{
		std::vector<std::atomic<int>> runs(count);
		pool.run(count, [&](size_t i) { ++runs[i]; });
		for (size_t i = 0; i < count; ++i) ASSERT_EQ(runs[i].load(), 1) << "count " << count << " index " << i;
	}
}

TEST(TaskPool, TasksRunOnSeveralThreadsAtOnce)
{
	// three tasks that each wait until all three have started: only possible
	// if they run at the same time (a plain loop would wait for ever; the
	// wait gives up after 10 s so the test fails instead of hanging)
	CTaskPool pool(3);
	std::atomic<int> started{0};
	std::mutex m;
	std::set<std::thread::id> ids;
	bool allMet = true;
	pool.run(3, [&](size_t) {
		++started;
		const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
		while (started.load() < 3 && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
		std::lock_guard<std::mutex> lock(m);
		allMet = allMet && started.load() == 3;
		ids.insert(std::this_thread::get_id());
	});
	EXPECT_TRUE(allMet);
	EXPECT_EQ(ids.size(), 3u);
}

TEST(TaskPool, RethrowsTheLowestIndexErrorAfterTheOthersFinished)
{
	CTaskPool pool(4);
	std::atomic<int> finished{0};
	try
	{
		pool.run(8, [&](size_t i) {
			if (i == 5) throw std::runtime_error("task 5");
			if (i == 2) throw std::runtime_error("task 2");
			++finished;
		});
		FAIL() << "no error rethrown";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_STREQ(e.what(), "task 2");
	}
	EXPECT_EQ(finished.load(), 6);
	pool.run(2, [&](size_t) { ++finished; });  // still usable
	EXPECT_EQ(finished.load(), 8);
}
