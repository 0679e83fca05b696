/* Fuzz target: a rawlog (plain bytes; the gz layer is zlib's) through
 * CRawlogReader: declared-size checks, MRPT deserialisation, resync. */
#include <hslam/io/CRawlogReader.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_rawlog_reader(const uint8_t* data, size_t size)
{
	static const std::string path = "/tmp/hslam_fuzz_rawlog_" + std::to_string(getpid()) + ".rawlog";
	std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
	try
	{
		io::CRawlogReader reader(path);
		io::TRawlogEntry entry;
		while (reader.next(entry))
		{
		}
	}
	catch (const io::rawlog_error&)
	{
	}
	std::remove(path.c_str());
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_rawlog_reader)
