/* hslam-bench: reading the simulator's truth CSVs (moved from bench_legs_sim.cpp). */
#include "bench_csv.h"

#include <hslam/io/CGzLineReader.h>
#include <hslam/io/csv_line.h>

#include <sstream>
#include <stdexcept>

namespace hslam::bench
{
/** Rows of a (gz) CSV as column name -> text. */
std::vector<std::map<std::string, std::string>> readCsv(const std::string& path)
{
	io::CGzLineReader in(path);
	std::string line;
	if (!in.nextLine(line)) throw std::runtime_error(path + ": empty file");
	const std::vector<std::string> header = io::splitCsvLine(line);
	std::vector<std::map<std::string, std::string>> rows;
	while (in.nextLine(line))
	{
		const std::vector<std::string> fields = io::splitCsvLine(line);
		if (fields.size() != header.size())
			throw std::runtime_error(path + ":" + std::to_string(in.lineNumber()) + ": " + std::to_string(fields.size()) +
									 " fields, header has " + std::to_string(header.size()));
		std::map<std::string, std::string> row;
		for (size_t k = 0; k < fields.size(); ++k) row[header[k]] = fields[k];
		rows.push_back(std::move(row));
	}
	return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& key, const std::string& file)
{
	const auto it = row.find(key);
	if (it == row.end()) throw std::runtime_error(file + ": no column '" + key + "'");
	try
	{
		return std::stod(it->second);
	}
	catch (const std::exception&)
	{
		throw std::runtime_error(file + ": column '" + key + "' value '" + it->second + "' is not a number");
	}
}

}  // namespace hslam::bench
