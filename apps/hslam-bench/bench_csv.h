/* hslam-bench: the simulator's truth CSVs (people.csv.gz, beam_labels.csv.gz). */
#pragma once

#include <map>
#include <string>
#include <vector>

namespace hslam::bench
{
/** Rows of a (gz) CSV as column name -> text; throws naming the file and line. */
std::vector<std::map<std::string, std::string>> readCsv(const std::string& path);

/** Column `key` of a row as a number; throws naming the file and column. */
double number(const std::map<std::string, std::string>& row, const std::string& key, const std::string& file);

}  // namespace hslam::bench
