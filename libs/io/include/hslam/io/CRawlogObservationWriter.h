/* hslam: incremental writer of an observations-only MRPT rawlog
 * (gz-compressed; one serialized CObservation after another), so that what
 * was converted before an error is on disk once the writer is closed. */
#pragma once

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservation.h>

#include <cstddef>
#include <map>
#include <string>

namespace hslam::io
{
class CRawlogObservationWriter
{
   public:
	/** Opens (truncates) `path`; throws std::runtime_error naming it on failure. */
	explicit CRawlogObservationWriter(const std::string& path);
	/** Closes the file if still open (never throws). */
	~CRawlogObservationWriter();
	CRawlogObservationWriter(const CRawlogObservationWriter&) = delete;
	CRawlogObservationWriter& operator=(const CRawlogObservationWriter&) = delete;

	/** Appends one observation; throws std::runtime_error on a write error. */
	void write(const mrpt::obs::CObservation& observation);

	/** Flushes and closes; further writes throw. Safe to call twice. */
	void close();

	size_t written() const { return m_written; }
	/** Number of observations written per sensor label. */
	const std::map<std::string, size_t>& writtenPerLabel() const { return m_perLabel; }

   private:
	std::string m_path;
	mrpt::io::CFileGZOutputStream m_out;
	size_t m_written = 0;
	std::map<std::string, size_t> m_perLabel;
};

}  // namespace hslam::io
