/* hslam: a few persistent threads that run the iterations of one loop
 * together: run(count, task) calls task(0) ... task(count - 1), each exactly
 * once, spread over the pool's threads and the caller's, and returns when all
 * are done.
 *
 * For independent pieces of one step (the loop-closure candidates of one
 * keyframe): each task writes only its own slot of a result vector, so the
 * result is the same as a plain loop's whatever the thread count and timing.
 * With 1 thread (or 0 extra) nothing runs concurrently: run() is that loop.
 *
 * Errors: run() rethrows the exception of the lowest-index task that threw
 * (tasks already started finish first; with no extra thread the loop stops
 * there). One run() at a time (not re-entrant from several caller threads). */
#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace hslam::common
{
class CTaskPool
{
   public:
	/** threads = how many run tasks at once, the caller included (0 or 1:
	 * none but the caller; callers choose the count, e.g. from
	 * std::thread::hardware_concurrency()). */
	explicit CTaskPool(size_t threads);
	~CTaskPool();
	CTaskPool(const CTaskPool&) = delete;
	CTaskPool& operator=(const CTaskPool&) = delete;

	/** Runs task(i) for every i in [0, count); returns when all have finished. */
	void run(size_t count, const std::function<void(size_t)>& task);

	/** Threads that run tasks at once, the caller included. */
	size_t threads() const { return m_workers.size() + 1; }

   private:
	void workerLoop();
	/** Takes and runs tasks of the current call until none is left. */
	void drainTasks(std::unique_lock<std::mutex>& lock);

	std::mutex m_mutex;
	std::condition_variable m_wake, m_done;
	const std::function<void(size_t)>* m_task = nullptr;
	size_t m_count = 0, m_next = 0, m_running = 0;
	std::vector<std::exception_ptr> m_errors;
	bool m_stop = false;
	std::vector<std::thread> m_workers;  //!< last: they start once the rest exists
};

}  // namespace hslam::common
