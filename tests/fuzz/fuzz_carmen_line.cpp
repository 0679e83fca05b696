/* Fuzz target: one CARMEN log line through CCarmenLineParser (libs/io). */
#include <hslam/io/CCarmenLineParser.h>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_carmen_line(const uint8_t* data, size_t size)
{
	try
	{
		io::CCarmenLineParser().parse(asText(data, size));
	}
	catch (const io::carmen_format_error&)
	{
	}
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_carmen_line)
