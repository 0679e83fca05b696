/* hslam: line-by-line reading of a plain or gzip-compressed text file through
 * zlib (gzopen/gzgets read both transparently), with line numbers for error
 * messages. Lines of any length are supported. */
#pragma once

#include <cstddef>
#include <string>

namespace hslam::io
{
class CGzLineReader
{
   public:
	/** Opens `path`; throws std::runtime_error naming the file if it cannot be opened. */
	explicit CGzLineReader(const std::string& path);
	~CGzLineReader();
	CGzLineReader(const CGzLineReader&) = delete;
	CGzLineReader& operator=(const CGzLineReader&) = delete;

	/** Reads the next line without its end-of-line characters ("\n", "\r\n").
	 * Returns false at the end of the file. Throws std::runtime_error
	 * ("file:line: ...") if the (gzip) stream is corrupt or truncated. */
	bool nextLine(std::string& line);

	/** 1-based number of the line returned by the last nextLine(). */
	size_t lineNumber() const { return m_lineNumber; }

	const std::string& path() const { return m_path; }

   private:
	void throwIfStreamError() const;

	std::string m_path;
	void* m_file = nullptr;  //!< gzFile (kept opaque so zlib.h stays out of the header)
	size_t m_lineNumber = 0;
	/** Decompressed bytes not yet returned: lines are split here, not by
	 * gzgets(), so a NUL byte stays inside its line (gzgets' C string would
	 * end at it and glue the next line on, issue 15 item 6). */
	std::string m_pending;
	size_t m_pendingPos = 0;
	bool m_ended = false;
};

}  // namespace hslam::io
