/* hslam: checks the sizes an MRPT object declares in a rawlog byte stream
 * before MRPT reads it (issue 15, item 1).
 *
 * MRPT's deserialisers read an element count and resize their arrays before
 * reading the elements, so one corrupt or crafted count (a scan with
 * 0x7fffffff beams) makes MRPT allocate gigabytes and crash. These checks read
 * the count from the serialised bytes of the classes found in rawlogs (MRPT
 * 2.5's current class versions, layouts measured from MRPT's own
 * WriteObject output; see docs/reliability.md) and refuse a count above a sane
 * limit or larger than the bytes the stream still holds. */
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace hslam::io
{
/** Outcome of checking one object header at the start of `data`. */
struct TDeclaredSizeCheck
{
	enum class EResult
	{
		NotChecked,  //!< not an object header of a checked class/version
		Plausible,
		NeedMoreBytes,  //!< call again with at least `bytes_needed` bytes (unless at end of stream)
		Absurd  //!< `message` says which size is impossible
	};
	EResult result = EResult::NotChecked;
	size_t bytes_needed = 0;
	std::string message;
};

/** Largest counts accepted (far above any real sensor). */
struct TDeclaredSizeLimits
{
	uint32_t max_scan_beams = 1u << 20;
	uint32_t max_range_sensors = 4096;
	uint32_t max_frame_objects = 65536;
	uint32_t max_label_chars = 4096;
	uint32_t max_comment_chars = 16u << 20;
};

/** Class names (with their header byte, 0x80 | length) whose sizes are checked. */
bool startsCheckedHeader(const uint8_t* data, size_t avail);

/** Checks the object header at `data` (avail bytes available; at_end: the
 * stream holds no more bytes than these). */
TDeclaredSizeCheck checkDeclaredSizes(const uint8_t* data, size_t avail, bool at_end,
									  const TDeclaredSizeLimits& limits = {});

}  // namespace hslam::io
