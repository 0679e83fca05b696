#include "CCheckedRawlogArchive.h"

#include <mrpt/rtti/CObject.h>

#include <algorithm>
#include <cstring>

namespace hslam::io
{
namespace
{
constexpr size_t READ_CHUNK = 1 << 16;
}  // namespace

void CCheckedRawlogArchive::fill(uint64_t offset, size_t n)
{
	while (!m_fileEnded && m_base + m_buf.size() < offset + n)
	{
		const size_t old = m_buf.size();
		m_buf.resize(old + READ_CHUNK);
		size_t got = 0;
		try
		{
			// gzread() returns -1 on corrupt compressed data: (size_t)-1 here.
			got = m_file.Read(m_buf.data() + old, READ_CHUNK);
			if (got > READ_CHUNK) m_streamError = "corrupt compressed data (zlib)";
		}
		catch (const std::exception& e)
		{
			m_streamError = e.what();
		}
		if (!m_streamError.empty()) got = 0;
		m_buf.resize(old + got);
		if (got == 0) m_fileEnded = true;
	}
}

bool CCheckedRawlogArchive::atEnd()
{
	fill(m_pos, 1);
	return availableFrom(m_pos) == 0;
}

void CCheckedRawlogArchive::discardConsumed()
{
	const size_t drop = static_cast<size_t>(m_pos - m_base);
	if (drop < (1u << 20)) return;  // erase in large steps only
	m_buf.erase(m_buf.begin(), m_buf.begin() + static_cast<std::ptrdiff_t>(drop));
	m_base = m_pos;
	m_headerByteAt = NO_HEADER;
}

void CCheckedRawlogArchive::checkHeaderAt(uint64_t h)
{
	fill(h, 128);
	if (!startsCheckedHeader(at(h), availableFrom(h))) return;
	for (;;)
	{
		const auto r = checkDeclaredSizes(at(h), availableFrom(h), m_fileEnded, m_limits);
		if (r.result == TDeclaredSizeCheck::EResult::Absurd)
			throw declared_size_error("declared size refused before reading (byte " + std::to_string(h) + "): " + r.message);
		if (r.result != TDeclaredSizeCheck::EResult::NeedMoreBytes) return;
		fill(h, r.bytes_needed);
	}
}

size_t CCheckedRawlogArchive::read(void* buf, size_t len)
{
	fill(m_pos, len);
	const size_t n = std::min(len, availableFrom(m_pos));
	// MRPT reads an object header (CArchive::internal_ReadObjectHeader) as one
	// byte, 0x80 | name length, then the name in one read of that length, then
	// the version. The header is checked at the name's read, still before the
	// counts: MRPT turns any exception on the first byte into "end of file".
	// Only where MRPT reads a header: bytes inside a field that happen to look
	// like one (a timestamp byte 0xA7 just before the next object's header
	// formed "...mrpt::obs::CObservationComment" with an absurd "count" in a
	// recorded rawlog) are data, and MRPT never reads them as a header.
	const bool readsHeaderName =
		n > 0 && m_headerByteAt != NO_HEADER && m_headerByteAt + 1 == m_pos && len == (*at(m_headerByteAt) & 0x7Fu);
	if (readsHeaderName) checkHeaderAt(m_headerByteAt);
	m_headerByteAt = (len == 1 && n == 1 && (*at(m_pos) & 0x80)) ? m_pos : NO_HEADER;
	std::memcpy(buf, at(m_pos), n);
	m_pos += n;
	return n;  // short read: CArchive throws CExceptionEOF
}

size_t CCheckedRawlogArchive::write(const void*, size_t) { throw std::logic_error("CCheckedRawlogArchive is read-only"); }

bool CCheckedRawlogArchive::seekNextObject(uint64_t from, const std::set<std::string>& classNames)
{
	for (uint64_t q = std::max<uint64_t>(from, m_base);; ++q)
	{
		fill(q, 130);
		if (availableFrom(q) == 0)
		{
			m_pos = q;
			return false;
		}
		const uint8_t b = *at(q);
		// Not required to follow an end flag (0x88): that flag may be the
		// damaged byte. A registered top-level class name is specific enough.
		if (!(b & 0x80)) continue;
		const size_t len = b & 0x7F;
		if (len == 0 || availableFrom(q) < 1 + len) continue;
		const std::string name(reinterpret_cast<const char*>(at(q + 1)), len);
		if (classNames.count(name) && mrpt::rtti::findRegisteredClass(name))
		{
			m_pos = q;
			m_headerByteAt = NO_HEADER;
			return true;
		}
	}
}

}  // namespace hslam::io
