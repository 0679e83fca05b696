/* common::CSerialWorker: items reach the consumer in push order, on one
 * thread other than the caller's; a consumer's error is rethrown to the
 * caller and the items after it are dropped. */
#include <gtest/gtest.h>
#include <hslam/common/CSerialWorker.h>

#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using hslam::common::CSerialWorker;

TEST(SerialWorker, ConsumesEveryItemInPushOrderOnOneOtherThread)
{
	std::vector<int> seen;
	std::set<std::thread::id> threads;
	{
		CSerialWorker<int> worker([&](int& v) {
			seen.push_back(v);
			threads.insert(std::this_thread::get_id());
		});
		for (int i = 0; i < 2000; ++i)
		{
			worker.push(i);
			if (i == 1000) worker.wait();  // a wait in the middle changes nothing
		}
		worker.wait();
		EXPECT_EQ(worker.pending(), 0u);
		ASSERT_EQ(seen.size(), 2000u);
	}
	for (int i = 0; i < 2000; ++i) ASSERT_EQ(seen[static_cast<size_t>(i)], i);
	ASSERT_EQ(threads.size(), 1u);
	EXPECT_NE(*threads.begin(), std::this_thread::get_id());
}

TEST(SerialWorker, RethrowsTheConsumersErrorAndDropsTheItemsAfterIt)
{
	std::vector<int> seen;
	CSerialWorker<int> worker([&](int& v) {
		if (v == 3) throw std::runtime_error("keyframe 3: bad scan");
		seen.push_back(v);
	});
	for (int i = 0; i < 3; ++i) worker.push(i);
	worker.wait();
	EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
	worker.push(3);
	try
	{
		worker.wait();
		FAIL() << "the consumer's error was not rethrown";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_STREQ(e.what(), "keyframe 3: bad scan");
	}
	EXPECT_THROW(worker.push(4), std::runtime_error);  // every later call fails too
	EXPECT_THROW(worker.wait(), std::runtime_error);
	EXPECT_EQ(seen, (std::vector<int>{0, 1, 2}));
}

TEST(SerialWorker, CountsWhatIsStillQueued)
{
	// the consumer holds the first item until released: the rest stay queued
	std::mutex gate;
	std::unique_lock<std::mutex> closed(gate);
	std::atomic<int> consumed{0};
	CSerialWorker<int> worker([&](int&) {
		std::lock_guard<std::mutex> pass(gate);
		++consumed;
	});
	for (int i = 0; i < 5; ++i) worker.push(i);
	EXPECT_EQ(worker.pending(), 5u);  // one held by the consumer, four queued
	closed.unlock();
	worker.wait();
	EXPECT_EQ(worker.pending(), 0u);
	EXPECT_EQ(consumed.load(), 5);
}
