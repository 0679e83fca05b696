#include "bench_report.h"

#include <iomanip>
#include <stdexcept>

namespace hslam::bench
{
void CReportTable::printHeader() const
{
	std::vector<std::string> headers;
	for (const auto& c : m_columns) headers.push_back(c.header);
	printRow(headers);
}

void CReportTable::printRow(const std::vector<std::string>& cells) const
{
	if (cells.size() != m_columns.size())
		throw std::logic_error("CReportTable: " + std::to_string(cells.size()) + " cells for " +
							   std::to_string(m_columns.size()) + " columns");
	for (size_t i = 0; i < cells.size(); ++i)
		m_out << (m_columns[i].left_aligned ? std::left : std::right) << std::setw(m_columns[i].width) << cells[i];
	m_out << std::right << "\n";
}

void CMarkdownTable::printHeader() const
{
	printRow(m_headers);
	printRow(std::vector<std::string>(m_headers.size(), "---"));
}

void CMarkdownTable::printRow(const std::vector<std::string>& cells) const
{
	if (cells.size() != m_headers.size())
		throw std::logic_error("CMarkdownTable: " + std::to_string(cells.size()) + " cells for " +
							   std::to_string(m_headers.size()) + " columns");
	m_out << "|";
	for (const auto& c : cells) m_out << " " << c << " |";
	m_out << "\n";
}

std::string fixed(double value, int decimals)
{
	std::ostringstream text;
	text << std::fixed << std::setprecision(decimals) << value;
	return text.str();
}

std::string padLeft(const std::string& text, int width)
{
	return text.size() >= static_cast<size_t>(width) ? text : std::string(width - text.size(), ' ') + text;
}

}  // namespace hslam::bench
