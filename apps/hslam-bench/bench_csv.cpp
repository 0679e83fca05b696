/* hslam-bench: reading the simulator's truth CSVs (moved from bench_legs_sim.cpp). */
#include "bench_csv.h"

#include <hslam/io/CGzLineReader.h>

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
	std::vector<std::string> header;
	std::stringstream hs(line);
	for (std::string h; std::getline(hs, h, ',');) header.push_back(h);
	std::vector<std::map<std::string, std::string>> rows;
	while (in.nextLine(line))
	{
		std::stringstream ls(line);
		std::map<std::string, std::string> row;
		size_t k = 0;
		for (std::string f; std::getline(ls, f, ','); ++k)
			if (k < header.size()) row[header[k]] = f;
		if (k != header.size())
			throw std::runtime_error(path + ":" + std::to_string(in.lineNumber()) + ": " + std::to_string(k) +
									 " fields, header has " + std::to_string(header.size()));
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
