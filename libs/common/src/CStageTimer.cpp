#include <hslam/common/CStageTimer.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace hslam::common
{
void CStageTimer::add(const std::string& stage, double seconds)
{
	auto it = m_samples_s.find(stage);
	if (it == m_samples_s.end())
	{
		m_order.push_back(stage);
		it = m_samples_s.emplace(stage, std::vector<double>{}).first;
	}
	it->second.push_back(seconds);
}

std::vector<TStageStats> CStageTimer::stats() const
{
	std::vector<TStageStats> out;
	for (const auto& stage : m_order)
	{
		std::vector<double> v = m_samples_s.at(stage);
		std::sort(v.begin(), v.end());
		TStageStats s;
		s.stage = stage;
		s.count = v.size();
		for (double x : v) s.total_ms += 1e3 * x;
		s.mean_ms = s.total_ms / static_cast<double>(v.size());
		// nearest-rank 95th percentile
		const size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
		s.p95_ms = 1e3 * v[std::max<size_t>(rank, 1) - 1];
		s.max_ms = 1e3 * v.back();
		out.push_back(s);
	}
	return out;
}

void CStageTimer::printTable(std::ostream& os) const
{
	os << std::left << std::setw(24) << "stage" << std::right << std::setw(8) << "calls" << std::setw(11)
	   << "mean ms" << std::setw(11) << "p95 ms" << std::setw(11) << "max ms" << std::setw(12) << "total ms"
	   << "\n";
	os << std::fixed << std::setprecision(3);
	for (const auto& s : stats())
		os << std::left << std::setw(24) << s.stage << std::right << std::setw(8) << s.count << std::setw(11)
		   << s.mean_ms << std::setw(11) << s.p95_ms << std::setw(11) << s.max_ms << std::setw(12) << s.total_ms
		   << "\n";
	os << std::defaultfloat;
}

void CStageTimer::writeCsv(std::ostream& os) const
{
	os << "stage,count,mean_ms,p95_ms,max_ms,total_ms\n";
	for (const auto& s : stats())
		os << s.stage << "," << s.count << "," << s.mean_ms << "," << s.p95_ms << "," << s.max_ms << ","
		   << s.total_ms << "\n";
}

CStageTimer::CScope::CScope(CStageTimer& timer, std::string stage)
	: m_timer(timer), m_stage(std::move(stage)), m_start(std::chrono::steady_clock::now())
{
}

CStageTimer::CScope::~CScope()
{
	const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - m_start;
	m_timer.add(m_stage, elapsed.count());
}

}  // namespace hslam::common
