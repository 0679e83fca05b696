/* hslam: flushable gzip rawlog writer (see CRawlogRecorder.h). */
#include <hslam/hwdrivers/CRawlogRecorder.h>
#include <mrpt/io/CStream.h>
#include <mrpt/serialization/CArchive.h>
#include <zlib.h>

#include <stdexcept>

namespace hslam::hwdrivers
{
/** Write-only mrpt::io::CStream over a zlib gzFile. */
class CRawlogRecorder::CGzStream : public mrpt::io::CStream
{
   public:
	CGzStream(const std::string& path, int level)
	{
		const std::string mode = "wb" + std::to_string(level);
		m_f = gzopen(path.c_str(), mode.c_str());
		if (!m_f) throw std::runtime_error("cannot create rawlog '" + path + "'");
	}
	~CGzStream() override { close(); }
	size_t Read(void*, size_t) override { throw std::logic_error("CRawlogRecorder stream is write-only"); }
	size_t Write(const void* buf, size_t n) override
	{
		if (!m_f) throw std::runtime_error("rawlog already closed");
		const int w = gzwrite(m_f, buf, static_cast<unsigned>(n));
		if (w <= 0 && n > 0) throw std::runtime_error("rawlog write failed (disk full?)");
		m_pos += static_cast<uint64_t>(w);
		return static_cast<size_t>(w);
	}
	uint64_t Seek(int64_t, CStream::TSeekOrigin) override { throw std::logic_error("not seekable"); }
	uint64_t getTotalBytesCount() const override { return m_pos; }
	uint64_t getPosition() const override { return m_pos; }
	void flush()
	{
		if (m_f) gzflush(m_f, Z_SYNC_FLUSH);
	}
	void close()
	{
		if (m_f) gzclose(m_f);
		m_f = nullptr;
	}

   private:
	gzFile m_f = nullptr;
	uint64_t m_pos = 0;
};

CRawlogRecorder::CRawlogRecorder(const std::string& path, int compressLevel)
	: m_path(path), m_stream(std::make_unique<CGzStream>(path, std::clamp(compressLevel, 0, 9)))
{
}

CRawlogRecorder::~CRawlogRecorder() { close(); }

void CRawlogRecorder::write(const mrpt::serialization::CSerializable& object)
{
	auto arch = mrpt::serialization::archiveFrom(*m_stream);
	arch << object;
	++m_objects;
}

void CRawlogRecorder::flush() { m_stream->flush(); }
void CRawlogRecorder::close()
{
	if (m_stream) m_stream->close();
}

}  // namespace hslam::hwdrivers
