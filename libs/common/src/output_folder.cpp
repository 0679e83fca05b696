#include <hslam/common/output_folder.h>

#include <sstream>
#include <hslam/common/output_paths.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

namespace hslam::common
{
namespace
{
namespace fs = std::filesystem;

bool isBookkeeping(const fs::path& name)
{
	return name == COutputFolder::LOCK_NAME || name == COutputFolder::MANIFEST_NAME ||
		   name.string().rfind(".hslam-tmp-", 0) == 0;
}

/** Relative paths of the regular files under `dir` (bookkeeping excluded). */
std::vector<std::string> filesUnder(const fs::path& dir)
{
	std::vector<std::string> files;
	for (const auto& e : fs::recursive_directory_iterator(dir))
		if (e.is_regular_file() && !isBookkeeping(e.path().filename()))
			files.push_back(fs::relative(e.path(), dir).generic_string());
	return files;
}

std::vector<std::string> readManifest(const fs::path& path)
{
	std::vector<std::string> files;
	std::ifstream in(path);
	for (std::string line; std::getline(in, line);)
		if (!line.empty() && line[0] != '#') files.push_back(line);
	return files;
}

/** A manifest entry is removed only if it stays inside the folder. */
bool insideFolder(const std::string& relative)
{
	const fs::path p(relative);
	if (p.is_absolute()) return false;
	for (const auto& part : p)
		if (part == "..") return false;
	return true;
}
}  // namespace

COutputFolder::COutputFolder(const std::string& dir, bool overwrite) : m_dir(dir)
{
	std::error_code ec;
	fs::create_directories(dir, ec);
	if (!fs::is_directory(dir)) throw output_folder_error("output folder '" + printableName(dir) + "': cannot create it");
	const std::string lockPath = (fs::path(dir) / LOCK_NAME).string();
	m_lockFd = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
	if (m_lockFd < 0) throw output_folder_error("output folder '" + printableName(dir) + "': cannot create " + LOCK_NAME);
	if (::flock(m_lockFd, LOCK_EX | LOCK_NB) != 0)
	{
		::close(m_lockFd);
		m_lockFd = -1;
		throw output_folder_error("output folder '" + printableName(dir) +
								  "' is in use by another run (locked); wait for it or choose another folder");
	}
	const bool ours = fs::exists(fs::path(dir) / MANIFEST_NAME);
	if (!ours && !overwrite && !filesUnder(dir).empty())
	{
		::close(m_lockFd);
		m_lockFd = -1;
		throw output_folder_error("output folder '" + printableName(dir) +
								  "' is not empty and was not written by hslam: refusing to mix results into it "
								  "(choose an empty folder, or pass --overwrite)");
	}
	if (ours) removeStaleOutputs();
	// Whatever is left was not written by this run (the user's files under
	// --overwrite, a log the shell opened before the run): never listed in
	// the manifest, so the next run never removes it.
	const auto left = filesUnder(dir);
	m_preexisting.insert(left.begin(), left.end());
}

COutputFolder::~COutputFolder()
{
	if (m_lockFd >= 0) ::close(m_lockFd);  // releases the flock
}

void COutputFolder::removeStaleOutputs()
{
	const fs::path dir(m_dir);
	std::set<fs::path> parents;
	for (const auto& rel : readManifest(dir / MANIFEST_NAME))
	{
		std::error_code ec;
		if (!insideFolder(rel) || !fs::remove(dir / rel, ec)) continue;
		m_staleRemoved.push_back(rel);
		for (fs::path p = fs::path(rel).parent_path(); !p.empty(); p = p.parent_path()) parents.insert(p);
	}
	// Folders the previous run made (tiles/, frames/), deepest first, if now empty.
	for (auto it = parents.rbegin(); it != parents.rend(); ++it)
	{
		std::error_code ec;
		if (fs::is_directory(dir / *it) && fs::is_empty(dir / *it)) fs::remove(dir / *it, ec);
	}
}

void COutputFolder::finish()
{
	std::string text = "# files written by the last hslam run into this folder (removed by the next run)\n";
	for (const auto& f : filesUnder(m_dir))
		if (!m_preexisting.count(f)) text += f + "\n";
	writeTextFileAtomically((fs::path(m_dir) / MANIFEST_NAME).string(), text);
}

void writeFileAtomically(const std::string& path, const std::function<void(const std::string&)>& writer)
{
	const fs::path target(path);
	const fs::path tmp = target.parent_path() / (".hslam-tmp-" + std::to_string(::getpid()) + "-" + target.filename().string());
	try
	{
		writer(tmp.string());
		if (!fs::exists(tmp)) throw std::runtime_error("nothing was written");
		fs::rename(tmp, target);
	}
	catch (const std::exception& e)
	{
		std::error_code ec;
		fs::remove(tmp, ec);
		throw std::runtime_error(printableName(path) + ": write failed or cut short (disk full?): " + e.what());
	}
}

void writeStreamAtomically(const std::string& path, const std::function<void(std::ostream&)>& writer)
{
	std::ostringstream text;
	writer(text);
	writeTextFileAtomically(path, text.str());
}

void writeTextFileAtomically(const std::string& path, const std::string& text)
{
	writeFileAtomically(path, [&text](const std::string& tmp) {
		std::FILE* f = std::fopen(tmp.c_str(), "wb");
		if (!f) throw std::runtime_error("cannot open for writing");
		const size_t n = std::fwrite(text.data(), 1, text.size(), f);
		const bool flushed = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
		if (std::fclose(f) != 0 || n != text.size() || !flushed)
			throw std::runtime_error("only " + std::to_string(n) + " of " + std::to_string(text.size()) + " bytes written");
	});
}

}  // namespace hslam::common
