/* hslam: CGzLineReader, zlib-based text line reader. */
#include <hslam/io/CGzLineReader.h>

#include <zlib.h>

#include <stdexcept>

namespace hslam::io
{
namespace
{
constexpr int kChunkBytes = 64 * 1024;  // one gzgets call; longer lines take several calls

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
	char chunk[kChunkBytes];
	bool readSomething = false;
	while (gzgets(asGz(m_file), chunk, kChunkBytes) != nullptr)
	{
		readSomething = true;
		line += chunk;
		if (!line.empty() && line.back() == '\n') break;
	}
	if (!readSomething)
	{
		throwIfStreamError();
		return false;
	}
	while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
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
