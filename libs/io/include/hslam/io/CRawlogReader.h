/* hslam: streaming reader for MRPT rawlogs in both formats (actions +
 * sensory frames, and observations only), gz-compressed or plain.
 *
 * Unlike mrpt::obs::CRawlog::getActionObservationPairOrObservation(), which
 * prints and returns "false" on a corrupt object as if the file had ended,
 * this reader tells a clean end of file from a corrupt or truncated one and
 * throws rawlog_error naming the file and the entry, so callers can keep what
 * they processed and report the fault. */
#pragma once

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace hslam::io
{
class rawlog_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** One rawlog entry: either an (actions, sensory frame) pair or one observation. */
struct TRawlogEntry
{
	mrpt::obs::CActionCollection::Ptr actions;  //!< SF format (may be null)
	mrpt::obs::CSensoryFrame::Ptr frame;  //!< SF format
	mrpt::obs::CObservation::Ptr observation;  //!< observations-only format
	size_t index = 0;  //!< 0-based entry number
};

class CRawlogReader
{
   public:
	/** Opens the file; throws rawlog_error if it does not exist or cannot be read. */
	explicit CRawlogReader(const std::string& path);

	/** Reads the next entry; false at a clean end of file. Throws rawlog_error
	 * ("<file>: entry N: ...") for corrupt or truncated content. */
	bool next(TRawlogEntry& entry);

	size_t entriesRead() const { return m_entries; }
	/** Objects of classes that are neither actions, frames nor observations. */
	size_t objectsSkipped() const { return m_skipped; }
	const std::string& path() const { return m_path; }

	/** Counts the entries of a file (stops quietly at the first fault). */
	static size_t countEntries(const std::string& path);

   private:
	mrpt::serialization::CSerializable::Ptr readObject(bool endAllowed);

	std::string m_path;
	mrpt::io::CFileGZInputStream m_file;
	std::unique_ptr<mrpt::serialization::CArchive> m_archive;
	size_t m_entries = 0, m_skipped = 0;
};

}  // namespace hslam::io
