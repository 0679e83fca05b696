/* hslam: one 64-bit key for a pair of integer grid indices (cells, tiles),
 * for the hash maps of sparse grids: x in the high 32 bits, y in the low 32
 * bits. Shifted as unsigned (a left shift of a negative value is undefined). */
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>

namespace hslam::common
{
inline int64_t cellKey(int ix, int iy)
{
	return static_cast<int64_t>(static_cast<uint64_t>(static_cast<int64_t>(ix)) << 32) ^ static_cast<uint32_t>(iy);
}

/** std::hash of cellKey(ix, iy). */
inline size_t cellKeyHash(int ix, int iy) { return std::hash<int64_t>()(cellKey(ix, iy)); }

}  // namespace hslam::common
