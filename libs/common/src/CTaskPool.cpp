#include <hslam/common/CTaskPool.h>

namespace hslam::common
{
CTaskPool::CTaskPool(size_t threads)
{
	for (size_t k = 1; k < threads; ++k) m_workers.emplace_back([this] { workerLoop(); });
}

CTaskPool::~CTaskPool()
{
	{
		std::lock_guard<std::mutex> lock(m_mutex);
		m_stop = true;
	}
	m_wake.notify_all();
	for (auto& t : m_workers) t.join();
}

void CTaskPool::drainTasks(std::unique_lock<std::mutex>& lock)
{
	while (m_task && m_next < m_count)
	{
		const size_t i = m_next++;
		const auto* task = m_task;
		++m_running;
		lock.unlock();
		std::exception_ptr error;
		try
		{
			(*task)(i);
		}
		catch (...)
		{
			error = std::current_exception();
		}
		lock.lock();
		if (error) m_errors[i] = error;
		if (--m_running == 0 && m_next >= m_count) m_done.notify_all();
	}
}

void CTaskPool::workerLoop()
{
	std::unique_lock<std::mutex> lock(m_mutex);
	for (;;)
	{
		m_wake.wait(lock, [this] { return m_stop || (m_task && m_next < m_count); });
		if (m_stop) return;
		drainTasks(lock);
	}
}

void CTaskPool::run(size_t count, const std::function<void(size_t)>& task)
{
	if (m_workers.empty() || count <= 1)
	{
		for (size_t i = 0; i < count; ++i) task(i);
		return;
	}
	std::unique_lock<std::mutex> lock(m_mutex);
	m_task = &task, m_count = count, m_next = 0, m_running = 0;
	m_errors.assign(count, nullptr);
	m_wake.notify_all();
	drainTasks(lock);
	m_done.wait(lock, [this] { return m_next >= m_count && m_running == 0; });
	m_task = nullptr, m_count = 0;
	for (const auto& e : m_errors)
		if (e) std::rethrow_exception(e);
}

}  // namespace hslam::common
