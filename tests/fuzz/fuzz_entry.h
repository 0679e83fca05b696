/* hslam fuzzing: each fuzz_<name>.cpp defines one entry function
 * `int fuzz_<name>(const uint8_t*, size_t)` (no crash, no leak, no undefined
 * behaviour for any input; the product's own exceptions are the expected
 * "clear error" outcome and are caught). HSLAM_FUZZ_ENTRY(name) makes it the
 * libFuzzer entry point when the file is built as a fuzz target
 * (-DHSLAM_LIBFUZZER, CMake option HSLAM_FUZZ); the normal build links every
 * entry into fuzz_replay, which replays the seed corpus and the kept crashers
 * (tests/fuzz/regressions/) as a CTest test. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#ifdef HSLAM_LIBFUZZER
#define HSLAM_FUZZ_ENTRY(name)                                                          \
	extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)             \
	{                                                                                   \
		return name(data, size);                                                        \
	}
#else
#define HSLAM_FUZZ_ENTRY(name)
#endif

namespace hslam::fuzz
{
int fuzz_carmen_line(const uint8_t* data, size_t size);
int fuzz_ini_options(const uint8_t* data, size_t size);
int fuzz_arcos_packets(const uint8_t* data, size_t size);
int fuzz_rawlog_reader(const uint8_t* data, size_t size);
int fuzz_tiled_map(const uint8_t* data, size_t size);
int fuzz_tum_reader(const uint8_t* data, size_t size);

inline std::string asText(const uint8_t* data, size_t size) { return std::string(reinterpret_cast<const char*>(data), size); }
}  // namespace hslam::fuzz
