/* hslam-bench: the report every suite prints, a readable table and then
 * key=value lines for scripts. */
#pragma once

#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace hslam::bench
{
/** One column of a table: its header, its width in characters (the header and
 * every cell are padded to it) and its alignment. */
struct TColumn
{
	std::string header;
	int width = 10;
	bool left_aligned = false;
};

/** A table of fixed-width columns printed row by row; cells are texts
 * (format numbers with fixed()). */
class CReportTable
{
   public:
	CReportTable(std::ostream& out, std::vector<TColumn> columns) : m_out(out), m_columns(std::move(columns)) {}

	void printHeader() const;
	/** One cell per column; throws std::logic_error on a wrong count. */
	void printRow(const std::vector<std::string>& cells) const;

   private:
	std::ostream& m_out;
	std::vector<TColumn> m_columns;
};

/** A markdown table: a header row, the `| --- |` separator row, then rows
 * of texts, each cell as given (no padding: markdown aligns the columns). */
class CMarkdownTable
{
   public:
	CMarkdownTable(std::ostream& out, std::vector<std::string> headers) : m_out(out), m_headers(std::move(headers)) {}

	/** The header row and the separator row. */
	void printHeader() const;
	/** `| a | b |`: one cell per column; throws std::logic_error on a wrong count. */
	void printRow(const std::vector<std::string>& cells) const;

   private:
	std::ostream& m_out;
	std::vector<std::string> m_headers;
};

/** `value` with `decimals` digits after the point (std::fixed). */
std::string fixed(double value, int decimals);

/** key=value lines: floating-point values with 6 significant digits
 * (std::defaultfloat) or, with `fixedDecimals` >= 0, that many digits after
 * the point (std::fixed); integers and texts as they are. */
class CKeyValueLines
{
   public:
	explicit CKeyValueLines(std::ostream& out, int fixedDecimals = -1) : m_out(out), m_fixedDecimals(fixedDecimals) {}

	template <class T>
	CKeyValueLines& operator()(const std::string& key, const T& value)
	{
		std::ostringstream text;
		if (m_fixedDecimals >= 0)
			text << std::fixed << std::setprecision(m_fixedDecimals);
		else
			text.precision(6);
		text << value;
		m_out << key << "=" << text.str() << "\n";
		return *this;
	}

   private:
	std::ostream& m_out;
	int m_fixedDecimals;
};

/** `text` right-aligned in `width` characters (a cell built from two figures). */
std::string padLeft(const std::string& text, int width);

}  // namespace hslam::bench
