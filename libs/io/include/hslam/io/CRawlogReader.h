/* hslam: streaming reader for MRPT rawlogs in both formats (actions +
 * sensory frames, and observations only), gz-compressed or plain.
 *
 * Unlike mrpt::obs::CRawlog::getActionObservationPairOrObservation(), which
 * prints and returns "false" on a corrupt object as if the file had ended,
 * this reader tells a clean end of file from a corrupt or truncated one:
 *  - object sizes declared in the stream are checked before MRPT reads them
 *    (a scan claiming 0x7fffffff beams is refused, not allocated);
 *  - after a corrupt or refused object the reader resynchronises on the next
 *    object header, records a TRawlogProblem (entry, byte offset, bytes
 *    skipped, why) and goes on, so a bit flip loses one entry, not the rest;
 *  - a file cut inside an object throws rawlog_error naming the file and the
 *    entry; so does a corruption with no object header after it.
 * Callers keep what they processed and report problems(). */
#pragma once

#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hslam::io
{
class CCheckedRawlogArchive;

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

/** A part of the file that was skipped. */
struct TRawlogProblem
{
	size_t entry = 0;  //!< entries read before it
	uint64_t offset = 0;  //!< byte offset (decompressed) of the bad object
	uint64_t skipped_bytes = 0;
	std::string message;  //!< "<file>: entry N: ..., skipped K bytes"
};

class CRawlogReader
{
   public:
	/** Opens the file; throws rawlog_error if it does not exist or cannot be read. */
	explicit CRawlogReader(const std::string& path);
	~CRawlogReader();

	/** Reads the next entry; false at the end of file. Skips (and records in
	 * problems()) corrupt objects followed by a readable one; throws
	 * rawlog_error ("<file>: entry N: ...") when the file is truncated or
	 * nothing readable follows a corruption. */
	bool next(TRawlogEntry& entry);

	size_t entriesRead() const { return m_entries; }
	/** Objects of classes that are neither actions, frames nor observations. */
	size_t objectsSkipped() const { return m_skipped; }
	const std::vector<TRawlogProblem>& problems() const { return m_problems; }
	/** One line per problem (empty if none). */
	std::string problemSummary() const;
	const std::string& path() const { return m_path; }

	/** Counts the entries of a file (stops quietly at the first fault). */
	static size_t countEntries(const std::string& path);

   private:
	mrpt::serialization::CSerializable::Ptr readObject(bool endAllowed);
	/** Records the failure of the object at `start` and moves to the next
	 * object; throws rawlog_error if there is none. */
	void skipBadObject(uint64_t start, const std::string& why);

	std::string m_path;
	mrpt::io::CFileGZInputStream m_file;
	std::unique_ptr<CCheckedRawlogArchive> m_archive;
	std::set<std::string> m_topLevelClasses;  //!< resynchronisation targets
	std::vector<TRawlogProblem> m_problems;
	mrpt::serialization::CSerializable::Ptr m_pending;  //!< object found by a resync inside a pair
	size_t m_entries = 0, m_skipped = 0;
};

}  // namespace hslam::io
