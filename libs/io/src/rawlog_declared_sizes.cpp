#include <hslam/io/rawlog_declared_sizes.h>

#include <array>
#include <cstring>
#include <functional>
#include <string_view>

namespace hslam::io
{
namespace
{
using EResult = TDeclaredSizeCheck::EResult;

uint32_t readU32(const uint8_t* p)
{
	return static_cast<uint32_t>(p[0]) | (static_cast<uint32_t>(p[1]) << 8) | (static_cast<uint32_t>(p[2]) << 16) |
		   (static_cast<uint32_t>(p[3]) << 24);
}

/** Bytes of a serialised CPose3D (v3: 12 doubles) / CPose2D (v1: 3 doubles),
 * header and end flag included, as written by MRPT 2.5. */
constexpr size_t POSE3D_BYTES = 1 + 20 + 1 + 96 + 1;
constexpr size_t POSE2D_BYTES = 1 + 20 + 1 + 24 + 1;

/** Reads the pieces of one layout, asking for more bytes when needed. */
class CLayoutCursor
{
   public:
	CLayoutCursor(const uint8_t* data, size_t avail, bool atEnd) : m_data(data), m_avail(avail), m_atEnd(atEnd) {}

	/** True if `n` bytes from `offset` are there; otherwise records the need. */
	bool have(size_t offset, size_t n)
	{
		if (offset + n <= m_avail) return true;
		m_need = offset + n;
		return false;
	}
	uint32_t u32(size_t offset) const { return readU32(m_data + offset); }
	uint8_t byte(size_t offset) const { return m_data[offset]; }
	TDeclaredSizeCheck missing() const
	{
		// At the end of the stream MRPT will hit the end itself (a clean error).
		if (m_atEnd) return {EResult::NotChecked, 0, ""};
		return {EResult::NeedMoreBytes, m_need, ""};
	}

   private:
	const uint8_t* m_data;
	size_t m_avail;
	bool m_atEnd;
	size_t m_need = 0;
};

TDeclaredSizeCheck absurd(const std::string& what) { return {EResult::Absurd, 0, what}; }

/** A nested pose object at `at` as MRPT 2.5 writes it: header byte, `name`
 * (20 chars), `version`, `doubles` doubles, end flag 0x88. Plausible if so,
 * NotChecked for another header byte (an older layout: MRPT's own checks),
 * Absurd for this header byte with another name, version or end: MRPT would
 * read the object's fields from the wrong offsets (found by fuzzing: a
 * mutated name made MRPT read a 1 GB string length out of the ranges). */
TDeclaredSizeCheck checkNestedPose(CLayoutCursor& c, size_t at, const char* name, uint8_t version, size_t doubles)
{
	const size_t nameLen = std::strlen(name), bytes = 1 + nameLen + 1 + 8 * doubles + 1;
	if (!c.have(at, bytes)) return c.missing();
	if (c.byte(at) != (0x80 | nameLen)) return {};
	for (size_t k = 0; k < nameLen; ++k)
		if (c.byte(at + 1 + k) != static_cast<uint8_t>(name[k])) return absurd(std::string("pose object is not a ") + name);
	if (c.byte(at + 1 + nameLen) != version) return absurd(std::string(name) + " version " + std::to_string(c.byte(at + 1 + nameLen)));
	if (c.byte(at + bytes - 1) != 0x88) return absurd(std::string(name) + " without its end flag");
	return {EResult::Plausible, 0, ""};
}
TDeclaredSizeCheck plausible() { return {EResult::Plausible, 0, ""}; }

/** A count that must not exceed `limit`, whose `bytesEach`-byte elements
 * (starting at `offset`) must fit in the stream. */
TDeclaredSizeCheck checkCount(CLayoutCursor& c, const std::string& what, uint32_t count, uint32_t limit, size_t offset,
							  size_t bytesEach)
{
	if (count > limit) return absurd(what + " " + std::to_string(count) + " > limit " + std::to_string(limit));
	// Within the limit but past the end of the stream: MRPT reports the
	// truncation itself (a bounded allocation).
	if (!c.have(offset, static_cast<size_t>(count) * bytesEach)) return c.missing();
	return plausible();
}

/** sensorLabel-like string (uint32 length + chars) at `offset`. */
TDeclaredSizeCheck checkString(CLayoutCursor& c, const std::string& what, size_t offset, uint32_t limit)
{
	if (!c.have(offset, 4)) return c.missing();
	return checkCount(c, what, c.u32(offset), limit, offset + 4, 1);
}

// CObservation2DRangeScan v7: aperture f32, rightToLeft u8, maxRange f32,
// sensorPose (CPose3D object), N u32, N f32 ranges, N u8 validity, stdError
// f32, timestamp u64, beamAperture f32, sensorLabel, ...
TDeclaredSizeCheck checkScan(CLayoutCursor& c, size_t body, uint8_t /*version*/, const TDeclaredSizeLimits& l)
{
	const size_t nAt = body + 4 + 1 + 4 + POSE3D_BYTES;
	auto pose = checkNestedPose(c, body + 9, "mrpt::poses::CPose3D", 3, 12);
	if (pose.result != EResult::Plausible) return pose;  // another layout, corrupt, or more bytes needed
	if (!c.have(nAt, 4)) return c.missing();
	const uint32_t n = c.u32(nAt);
	auto r = checkCount(c, "beam count", n, l.max_scan_beams, nAt + 4, 5);
	if (r.result != EResult::Plausible) return r;
	return checkString(c, "sensor label length", nAt + 4 + 5 * size_t(n) + 4 + 8 + 4, l.max_label_chars);
}

// CObservationRange v0-v3: min, max, cone f32, N u32, N x ([v3: id u16],
// CPose3D, range f32), [v1+: label]. Every version reads N and resizes first.
TDeclaredSizeCheck checkRange(CLayoutCursor& c, size_t body, uint8_t version, const TDeclaredSizeLimits& l)
{
	const size_t nAt = body + 12;
	if (!c.have(nAt, 4)) return c.missing();
	const uint32_t n = c.u32(nAt);
	const size_t each = (version >= 3 ? 2 : 0) + POSE3D_BYTES + 4;
	auto r = checkCount(c, "range sensor count", n, l.max_range_sensors, nAt + 4, each);
	if (r.result != EResult::Plausible || version < 1) return r;
	return checkString(c, "sensor label length", nAt + 4 + each * size_t(n), l.max_label_chars);
}

// CSensoryFrame v2 / CActionCollection v0: N u32, then N objects (>= 4 bytes each).
TDeclaredSizeCheck checkCollection(CLayoutCursor& c, size_t body, uint8_t /*version*/, const TDeclaredSizeLimits& l)
{
	if (!c.have(body, 4)) return c.missing();
	return checkCount(c, "object count", c.u32(body), l.max_frame_objects, body + 4, 4);
}

// CObservationComment v0: text (u32 length + chars).
TDeclaredSizeCheck checkComment(CLayoutCursor& c, size_t body, uint8_t /*version*/, const TDeclaredSizeLimits& l)
{
	return checkString(c, "comment length", body, l.max_comment_chars);
}

// CObservationOdometry v2: odometry (CPose2D object), sensorLabel, ...
TDeclaredSizeCheck checkOdometry(CLayoutCursor& c, size_t body, uint8_t /*version*/, const TDeclaredSizeLimits& l)
{
	auto pose = checkNestedPose(c, body, "mrpt::poses::CPose2D", 1, 3);
	if (pose.result != EResult::Plausible) return pose;
	return checkString(c, "sensor label length", body + POSE2D_BYTES, l.max_label_chars);
}

struct TCheckedClass
{
	const char* name;
	uint8_t min_version, max_version;  //!< the serialisation versions whose layout the check knows
	TDeclaredSizeCheck (*check)(CLayoutCursor&, size_t, uint8_t, const TDeclaredSizeLimits&);
};

const std::array<TCheckedClass, 6> CHECKED{{
	{"mrpt::obs::CObservation2DRangeScan", 7, 7, checkScan},
	{"mrpt::obs::CObservationRange", 0, 3, checkRange},
	{"mrpt::obs::CSensoryFrame", 2, 2, checkCollection},
	{"mrpt::obs::CActionCollection", 0, 0, checkCollection},
	{"mrpt::obs::CObservationComment", 0, 0, checkComment},
	{"mrpt::obs::CObservationOdometry", 2, 2, checkOdometry},
}};

/** The part of a class name after its last "::". */
std::string_view shortName(std::string_view name)
{
	const size_t colons = name.rfind("::");
	return colons == std::string_view::npos ? name : name.substr(colons + 2);
}

/** The checked class whose header starts `data`. Compared by the name after
 * the last "::" and before any NUL, as MRPT's class lookup resolves names
 * (an old or damaged namespace, "mrpt::ocs::CObservation2DRangeScan" or
 * "CObservation2DRangeScan", still reads as the scan: found by fuzzing). */
const TCheckedClass* matchHeader(const uint8_t* data, size_t avail)
{
	if (avail < 1 || !(data[0] & 0x80)) return nullptr;
	const size_t len = data[0] & 0x7F;
	if (avail < 1 + len) return nullptr;
	// MRPT makes a C string of the stored name: it ends at the first NUL
	// ("mrpt::obs::CObservationRange" padded with three NULs still reads as
	// the range observation: found by fuzzing, a declared count of 16.8 M
	// sensors that went unchecked)
	std::string_view stored(reinterpret_cast<const char*>(data + 1), len);
	stored = shortName(stored.substr(0, stored.find('\0')));
	for (const auto& k : CHECKED)
		if (shortName(k.name) == stored) return &k;
	return nullptr;
}
}  // namespace

bool startsCheckedHeader(const uint8_t* data, size_t avail) { return matchHeader(data, avail) != nullptr; }

TDeclaredSizeCheck checkDeclaredSizes(const uint8_t* data, size_t avail, bool at_end, const TDeclaredSizeLimits& limits)
{
	const TCheckedClass* k = matchHeader(data, avail);
	if (!k) return {};
	const size_t versionAt = 1 + (data[0] & 0x7F);
	CLayoutCursor c(data, avail, at_end);
	if (!c.have(versionAt, 1)) return c.missing();
	const uint8_t version = c.byte(versionAt);
	if (version < k->min_version || version > k->max_version) return {};  // other versions: MRPT's own checks only
	auto r = k->check(c, versionAt + 1, version, limits);
	if (r.result == EResult::Absurd) r.message = std::string(k->name) + ": " + r.message;
	return r;
}

}  // namespace hslam::io
