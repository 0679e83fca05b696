/* hslam: the byte source of CRawlogReader (private to libs/io).
 *
 * An MRPT CArchive over the (gz or plain) rawlog file that
 *  - keeps a window of the decompressed bytes, so a failed object can be
 *    skipped by searching the next object header (resynchronisation);
 *  - checks the declared sizes of every object header of a known class
 *    (rawlog_declared_sizes.h) that MRPT reads, nested ones included, before
 *    handing MRPT the bytes of that header's name, and throws
 *    declared_size_error for an absurd one: MRPT never sees the count, so it
 *    never allocates for it. */
#pragma once

#include <hslam/io/rawlog_declared_sizes.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hslam::io
{
class declared_size_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

class CCheckedRawlogArchive : public mrpt::serialization::CArchive
{
   public:
	explicit CCheckedRawlogArchive(mrpt::io::CFileGZInputStream& file) : m_file(file) {}

	/** Absolute offset (decompressed bytes) of the next byte MRPT reads. */
	uint64_t position() const { return m_pos; }
	/** Why the byte stream ended early ("" at a normal end of file). */
	const std::string& streamError() const { return m_streamError; }
	/** True if no byte is left. */
	bool atEnd();
	/** Forgets the bytes before the current position (call between objects). */
	void discardConsumed();
	/** From `from`, searches the next header of a class in `classNames`; moves there and returns true, or moves to
	 * the end of the stream and returns false. */
	bool seekNextObject(uint64_t from, const std::set<std::string>& classNames);

   protected:
	size_t write(const void*, size_t) override;
	size_t read(void* buf, size_t len) override;

   private:
	/** Makes bytes [offset, offset + n) available if the stream has them. */
	void fill(uint64_t offset, size_t n);
	/** Checks the declared sizes of the object header at `h` if its class is a checked one. */
	void checkHeaderAt(uint64_t h);
	const uint8_t* at(uint64_t offset) const { return m_buf.data() + (offset - m_base); }
	size_t availableFrom(uint64_t offset) const { return static_cast<size_t>(m_base + m_buf.size() - offset); }

	mrpt::io::CFileGZInputStream& m_file;
	std::vector<uint8_t> m_buf;  //!< bytes [m_base, m_base + size)
	static constexpr uint64_t NO_HEADER = ~uint64_t{0};
	uint64_t m_base = 0, m_pos = 0;
	uint64_t m_headerByteAt = NO_HEADER;  //!< offset of a 1-byte read of a header's first byte (0x80 | length)
	bool m_fileEnded = false;
	std::string m_streamError;
	TDeclaredSizeLimits m_limits;
};

}  // namespace hslam::io
