/* hslam: an output folder owned by one run at a time (issue 15, item 3).
 *
 * COutputFolder, held for the whole run:
 *  - creates the folder and takes an exclusive flock() on DIR/.hslam-lock, so
 *    a second run into the same folder fails at once instead of mixing files;
 *  - refuses a non-empty folder that is not an hslam output folder (no
 *    DIR/.hslam-manifest) unless `overwrite`, so a typo cannot scatter results
 *    into (or later clean) someone's folder;
 *  - removes the files the previous run listed in its manifest (old tiles,
 *    frames/, evaluation.json), so no stale result sits beside new ones;
 *  - finish() lists this run's files in the manifest (written atomically);
 *    files that were there before the run are never listed, so never removed.
 * writeFileAtomically(): temporary name in the same folder, then rename(); a
 * failed or cut-short write (full disk) throws naming the file and leaves
 * any previous version untouched. */
#pragma once

#include <functional>
#include <iosfwd>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace hslam::common
{
class output_folder_error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

class COutputFolder
{
   public:
	static constexpr const char* LOCK_NAME = ".hslam-lock";
	static constexpr const char* MANIFEST_NAME = ".hslam-manifest";

	/** Throws output_folder_error (naming the folder) if it is locked by
	 * another run, cannot be created, or is foreign and non-empty without
	 * `overwrite`. */
	COutputFolder(const std::string& dir, bool overwrite);
	~COutputFolder();
	COutputFolder(const COutputFolder&) = delete;
	COutputFolder& operator=(const COutputFolder&) = delete;

	/** Files of the previous run removed at construction (relative paths). */
	const std::vector<std::string>& staleRemoved() const { return m_staleRemoved; }

	/** Writes the manifest: the files now in the folder that were not there
	 * when the run started (this run's). */
	void finish();

   private:
	void removeStaleOutputs();

	std::string m_dir;
	int m_lockFd = -1;
	std::vector<std::string> m_staleRemoved;
	std::set<std::string> m_preexisting;  //!< files not written by this run
};

/** Calls writer(temporaryPath), checks the file is there, then renames it to
 * `path`. Throws std::runtime_error "<path>: ..." if the writer throws or the
 * rename fails; the temporary file is removed. */
void writeFileAtomically(const std::string& path, const std::function<void(const std::string& temporaryPath)>& writer);

/** writeFileAtomically() for text; checks every byte reached the disk. */
void writeTextFileAtomically(const std::string& path, const std::string& text);

/** writeTextFileAtomically() of what `writer` puts into a stream. */
void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream&)>& writer);

}  // namespace hslam::common
