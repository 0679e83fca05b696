#include <hslam/common/CProgressBar.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace hslam::common
{
CProgressBar::CProgressBar(std::ostream& os, bool isTerminal, size_t total, std::string unit)
	: m_os(os),
	  m_isTerminal(isTerminal),
	  m_total(total),
	  m_unit(std::move(unit)),
	  m_start(std::chrono::steady_clock::now()),
	  m_lastDraw(m_start)
{
}

bool CProgressBar::stderrIsTerminal() { return ::isatty(STDERR_FILENO) != 0; }

void CProgressBar::update(size_t done)
{
	m_done = done;
	const auto now = std::chrono::steady_clock::now();
	if (m_isTerminal)
	{
		if (now - m_lastDraw < std::chrono::milliseconds(100)) return;
		m_lastDraw = now;
		draw(done, false);
		return;
	}
	if (m_total == 0) return;
	const int decile = static_cast<int>(10 * done / m_total);
	if (decile > m_lastDecile && decile < 10)
	{
		m_lastDecile = decile;
		draw(done, false);
	}
}

void CProgressBar::finish() { draw(m_done, true); }

void CProgressBar::draw(size_t done, bool final)
{
	const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - m_start;
	std::ostringstream line;
	if (m_total > 0)
	{
		const double fraction = std::min(1.0, static_cast<double>(done) / static_cast<double>(m_total));
		const int width = 30, filled = static_cast<int>(fraction * width);
		line << "[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << std::setw(3)
			 << static_cast<int>(100 * fraction) << "%  " << done << "/" << m_total;
	}
	else
		line << done;
	line << " " << m_unit << "  " << std::fixed << std::setprecision(1) << elapsed.count() << " s";
	if (m_isTerminal)
		m_os << "\r" << line.str() << (final ? "\n" : "") << std::flush;
	else
		m_os << line.str() << "\n" << std::flush;
}

}  // namespace hslam::common
