/* Fuzz target: deserialisation of the tiled map (CTiledOccupancyGridMap2D,
 * libs/maps) from an MRPT archive, as rawlog-edit / a .simplemap would. */
#include <hslam/maps/CTiledOccupancyGridMap2D.h>
#include <mrpt/serialization/archiveFrom_std_vector.h>

#include "fuzz_entry.h"

namespace hslam::fuzz
{
int fuzz_tiled_map(const uint8_t* data, size_t size)
{
	maps::registerTiledMapClasses();
	const std::vector<uint8_t> bytes(data, data + size);
	auto in = mrpt::serialization::archiveFrom(bytes);
	try
	{
		maps::CTiledOccupancyGridMap2D map;
		in.ReadObject(&map);
	}
	catch (const std::exception&)  // MRPT's EOF / bad version / our config_error
	{
	}
	return 0;
}
}  // namespace hslam::fuzz

HSLAM_FUZZ_ENTRY(hslam::fuzz::fuzz_tiled_map)
