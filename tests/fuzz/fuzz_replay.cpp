/* fuzz_replay TARGET DIR...: runs every file of the given folders through the
 * fuzz target's entry function (the normal build's regression test for the
 * seed corpus and the crashers kept in tests/fuzz/regressions/). Exit 0 if
 * all ran; a crash or sanitizer report fails the CTest test. */
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <map>

#include "fuzz_entry.h"

int main(int argc, char** argv)
{
	using namespace hslam::fuzz;
	const std::map<std::string, int (*)(const uint8_t*, size_t)> targets{
		{"carmen_line", fuzz_carmen_line}, {"ini_options", fuzz_ini_options}, {"arcos_packets", fuzz_arcos_packets},
		{"rawlog_reader", fuzz_rawlog_reader}, {"tiled_map", fuzz_tiled_map}, {"tum_reader", fuzz_tum_reader}};
	if (argc < 3 || !targets.count(argv[1]))
	{
		std::cerr << "usage: fuzz_replay TARGET DIR...\n";
		return 2;
	}
	size_t files = 0;
	for (int a = 2; a < argc; ++a)
	{
		if (!std::filesystem::is_directory(argv[a])) continue;
		for (const auto& e : std::filesystem::directory_iterator(argv[a]))
		{
			if (!e.is_regular_file()) continue;
			std::ifstream f(e.path(), std::ios::binary);
			const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
			targets.at(argv[1])(bytes.data(), bytes.size());
			++files;
		}
	}
	std::cout << argv[1] << ": " << files << " inputs replayed\n";
	return files > 0 ? 0 : 1;
}
