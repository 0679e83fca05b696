/* hslam: rawlog file writer for recorders that may be stopped at any moment.
 *
 * gzip output through zlib with a sync flush after every write period
 * (flush()), so a file cut by SIGKILL or power loss is still readable up to
 * the last flush; close() (normal stop, SIGINT, SIGTERM) finishes the stream.
 * MRPT's CFileGZOutputStream cannot flush, which is one reason MRPT's
 * rawlog-grabber leaves an empty file when killed. */
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <cstdint>
#include <memory>
#include <string>

namespace hslam::hwdrivers
{
class CRawlogRecorder
{
   public:
	/** Opens `path` for writing, compression level 0..9; throws std::runtime_error. */
	CRawlogRecorder(const std::string& path, int compressLevel = 1);
	~CRawlogRecorder();
	CRawlogRecorder(const CRawlogRecorder&) = delete;
	CRawlogRecorder& operator=(const CRawlogRecorder&) = delete;

	void write(const mrpt::serialization::CSerializable& object);
	/** Makes everything written so far readable from the file. */
	void flush();
	void close();

	uint64_t objectsWritten() const { return m_objects; }
	const std::string& path() const { return m_path; }

   private:
	class CGzStream;
	std::string m_path;
	std::unique_ptr<CGzStream> m_stream;
	uint64_t m_objects = 0;
};

}  // namespace hslam::hwdrivers
