/* hslam: progress display for long batch work. On a terminal it redraws one
 * line ("[#####.....]  45%  120/224 scans  3.2 s"); when the stream is not a
 * terminal (CI, files) it prints one line per 10 % so logs stay short. */
#pragma once

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

namespace hslam::common
{
class CProgressBar
{
   public:
	/** total = 0 means unknown (shows a counter only). */
	CProgressBar(std::ostream& os, bool isTerminal, size_t total, std::string unit);

	void update(size_t done);
	void finish();

	/** True if stderr is an interactive terminal. */
	static bool stderrIsTerminal();

   private:
	void draw(size_t done, bool final);

	std::ostream& m_os;
	bool m_isTerminal;
	size_t m_total;
	std::string m_unit;
	int m_lastDecile = -1;
	size_t m_done = 0;
	std::chrono::steady_clock::time_point m_start, m_lastDraw;
};

}  // namespace hslam::common
