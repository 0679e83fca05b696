/* hslam: per-stage wall-clock statistics (mean, p95, max per call), the one
 * place where the pipeline's timing summary is computed. */
#pragma once

#include <chrono>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace hslam::common
{
struct TStageStats
{
	std::string stage;
	size_t count = 0;
	double mean_ms = 0, p95_ms = 0, max_ms = 0, total_ms = 0;
};

class CStageTimer
{
   public:
	/** Records one duration (seconds) for a stage. Stages keep first-use order. */
	void add(const std::string& stage, double seconds);

	/** Statistics of every stage, in first-use order. */
	std::vector<TStageStats> stats() const;

	/** A human-readable table. */
	void printTable(std::ostream& os) const;

	/** CSV: stage,count,mean_ms,p95_ms,max_ms,total_ms */
	void writeCsv(std::ostream& os) const;

	/** Times a scope and records it on destruction. */
	class CScope
	{
	   public:
		CScope(CStageTimer& timer, std::string stage);
		~CScope();
		CScope(const CScope&) = delete;
		CScope& operator=(const CScope&) = delete;

	   private:
		CStageTimer& m_timer;
		std::string m_stage;
		std::chrono::steady_clock::time_point m_start;
	};

   private:
	std::vector<std::string> m_order;
	std::map<std::string, std::vector<double>> m_samples_s;
};

}  // namespace hslam::common
