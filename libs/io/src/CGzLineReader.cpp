/* hslam: CGzLineReader, zlib-based text line reader. */
#include <hslam/io/CGzLineReader.h>

#include <zlib.h>

#include <stdexcept>

namespace hslam::io
{
namespace
{
constexpr int kChunkBytes = 64 * 1024;  // one gzread call

gzFile asGz(void* f) { return static_cast<gzFile>(f); }
}  // namespace

CGzLineReader::CGzLineReader(const std::string& path) : m_path(path)
{
	m_file = gzopen(path.c_str(), "rb");
	if (!m_file) throw std::runtime_error(path + ": cannot open for reading");
	gzbuffer(asGz(m_file), 256 * 1024);
}

CGzLineReader::~CGzLineReader()
{
	if (m_file) gzclose(asGz(m_file));
}

bool CGzLineReader::nextLine(std::string& line)
{
	line.clear();
	for (;;)
	{
		const size_t eol = m_pending.find('\n', m_pendingPos);
		if (eol != std::string::npos)
		{
			line.append(m_pending, m_pendingPos, eol - m_pendingPos);
			m_pendingPos = eol + 1;
			break;
		}
		line.append(m_pending, m_pendingPos, std::string::npos);
		m_pending.clear();
		m_pendingPos = 0;
		if (!m_ended)
		{
			m_pending.resize(kChunkBytes);
			const int n = gzread(asGz(m_file), m_pending.data(), kChunkBytes);
			m_pending.resize(n > 0 ? static_cast<size_t>(n) : 0);
			if (n <= 0)
			{
				m_ended = true;
				throwIfStreamError();
			}
			continue;
		}
		if (line.empty()) return false;  // clean end of file
		break;  // last line without a newline
	}
	while (!line.empty() && line.back() == '\r') line.pop_back();
	++m_lineNumber;
	return true;
}

void CGzLineReader::throwIfStreamError() const
{
	int code = Z_OK;
	const char* message = gzerror(asGz(m_file), &code);
	if (code == Z_OK || code == Z_STREAM_END) return;
	throw std::runtime_error(m_path + ":" + std::to_string(m_lineNumber + 1) +
							 ": corrupt or truncated file (zlib: " + (message ? message : "unknown error") + ")");
}

}  // namespace hslam::io
