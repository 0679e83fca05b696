/* Fuzz target: TUM trajectory text through parseTum (libs/common), the
 * reader of hslam-evaluate and --ground-truth. */
#include <hslam/common/tum_trajectory.h>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_tum_reader(const uint8_t* data, size_t size)
{
	try
	{
		common::parseTum(asText(data, size), "fuzz.tum");
	}
	catch (const std::runtime_error&)
	{
	}
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_tum_reader)
