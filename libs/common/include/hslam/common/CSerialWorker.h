/* hslam: one background thread that hands queued items, in the order they
 * were pushed, to one consumer.
 *
 * Used where a stage only consumes what the rest of the pipeline produces
 * and gives nothing back until the end (the loop-closure back-end: the
 * front-end never reads its graph online). The consumer sees the same items
 * in the same order as a direct call would, on one thread, so what it
 * computes does not depend on timing: the result is the synchronous one,
 * only the wall time changes (Cartographer runs its constraint search the
 * same way, in the background).
 *
 * Errors: an exception thrown by the consumer is kept; the items after it
 * are dropped, and push() and wait() rethrow it (every call), so the caller
 * fails with the consumer's own message. The destructor drops items not yet
 * started and joins the thread (it never throws). Not copyable. */
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <utility>

namespace hslam::common
{
template <class T>
class CSerialWorker
{
   public:
	using Consumer = std::function<void(T&)>;

	explicit CSerialWorker(Consumer consume) : m_consume(std::move(consume)), m_thread([this] { run(); }) {}

	~CSerialWorker()
	{
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			m_stop = true;
		}
		m_wake.notify_all();
		m_thread.join();
	}

	CSerialWorker(const CSerialWorker&) = delete;
	CSerialWorker& operator=(const CSerialWorker&) = delete;

	/** Queues one item (rethrows an earlier failure of the consumer). */
	void push(T item)
	{
		{
			std::lock_guard<std::mutex> lock(m_mutex);
			if (m_failure) std::rethrow_exception(m_failure);
			m_queue.push_back(std::move(item));
		}
		m_wake.notify_one();
	}

	/** Returns once every item pushed so far has been consumed (rethrows a
	 * failure of the consumer). */
	void wait()
	{
		std::unique_lock<std::mutex> lock(m_mutex);
		m_idle.wait(lock, [this] { return m_queue.empty() && !m_busy; });
		if (m_failure) std::rethrow_exception(m_failure);
	}

	/** Items pushed and not yet consumed (the one in progress included). */
	size_t pending()
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		return m_queue.size() + (m_busy ? 1 : 0);
	}

   private:
	void run()
	{
		std::unique_lock<std::mutex> lock(m_mutex);
		for (;;)
		{
			m_wake.wait(lock, [this] { return m_stop || !m_queue.empty(); });
			if (m_stop) return;
			T item = std::move(m_queue.front());
			m_queue.pop_front();
			m_busy = true;
			lock.unlock();
			std::exception_ptr failure;
			try
			{
				m_consume(item);
			}
			catch (...)
			{
				failure = std::current_exception();
			}
			lock.lock();
			m_busy = false;
			if (failure && !m_failure) m_failure = failure, m_queue.clear();
			if (m_queue.empty()) m_idle.notify_all();
		}
	}

	Consumer m_consume;
	std::mutex m_mutex;
	std::condition_variable m_wake, m_idle;
	std::deque<T> m_queue;
	bool m_busy = false, m_stop = false;
	std::exception_ptr m_failure;
	std::thread m_thread;  //!< last: starts after every other member exists
};

}  // namespace hslam::common
