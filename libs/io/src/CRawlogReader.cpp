#include <hslam/io/CRawlogReader.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>
#include <utility>

#include "CCheckedRawlogArchive.h"

namespace hslam::io
{
namespace
{
/** Resynchronisation targets before any object was read: every class of mrpt::obs. */
std::set<std::string> observationClasses()
{
	std::set<std::string> names;
	for (const auto* c : mrpt::rtti::getAllRegisteredClasses())
	{
		const std::string n = c->className;
		if (n.rfind("mrpt::obs::", 0) == 0) names.insert(n);
	}
	return names;
}

std::string shortened(std::string what)
{
	if (what.size() > 300) what = what.substr(0, 300) + "...";
	return what;
}
}  // namespace

CRawlogReader::CRawlogReader(const std::string& path) : m_path(path)
{
	if (!std::filesystem::is_regular_file(path)) throw rawlog_error(path + ": rawlog file not found");
	if (!m_file.open(path)) throw rawlog_error(path + ": cannot open rawlog file");
	m_archive = std::make_unique<CCheckedRawlogArchive>(m_file);
}

CRawlogReader::~CRawlogReader() = default;

void CRawlogReader::skipBadObject(uint64_t start, const std::string& why)
{
	const std::string where = m_path + ": entry " + std::to_string(m_entries) + ": ";
	const auto targets = m_topLevelClasses.empty() ? observationClasses() : m_topLevelClasses;
	if (!m_archive->seekNextObject(start + 1, targets))
		throw rawlog_error(where + why + " (no readable object after byte " + std::to_string(start) + ")");
	TRawlogProblem p;
	p.entry = m_entries;
	p.offset = start;
	p.skipped_bytes = m_archive->position() - start;
	p.message = where + why + "; skipped " + std::to_string(p.skipped_bytes) + " bytes from byte " + std::to_string(start);
	m_problems.push_back(std::move(p));
}

mrpt::serialization::CSerializable::Ptr CRawlogReader::readObject(bool endAllowed)
{
	for (;;)
	{
		m_archive->discardConsumed();
		const uint64_t start = m_archive->position();
		if (endAllowed && m_archive->atEnd())
		{
			if (!m_archive->streamError().empty())
				throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) + ": " + m_archive->streamError());
			return nullptr;
		}
		try
		{
			return m_archive->ReadObject();
		}
		catch (const declared_size_error& e)
		{
			skipBadObject(start, e.what());
		}
		catch (const std::exception& e)
		{
			// MRPT reports an end of file inside an object either as
			// CExceptionEOF or wrapped in a parse error: the stream position tells.
			if (m_archive->atEnd())
			{
				const std::string& why = m_archive->streamError();
				throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) +
								   (why.empty() ? ": file is truncated (ends inside an object)" : ": " + why));
			}
			skipBadObject(start, "corrupt data: " + shortened(e.what()));
		}
	}
}

bool CRawlogReader::next(TRawlogEntry& entry)
{
	entry = TRawlogEntry();
	for (;;)
	{
		auto object = m_pending ? std::exchange(m_pending, nullptr) : readObject(true);
		if (!object) return false;
		if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object))
			entry.observation = obs;
		else if (auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object))
			entry.frame = frame;
		else if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(object))
		{
			entry.actions = actions;
			const size_t problemsBefore = m_problems.size();
			auto second = readObject(false);
			entry.frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(second);
			if (!entry.frame && second && m_problems.size() > problemsBefore)
			{
				// Its frame was skipped (corrupt): the pair is dropped and the
				// object found by the resynchronisation starts the next entry.
				m_pending = second;
				entry = TRawlogEntry();
				continue;
			}
			if (!entry.frame)
				throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) +
								   ": an action collection is not followed by a sensory frame");
		}
		else
		{
			++m_skipped;
			continue;
		}
		m_topLevelClasses.insert(object->GetRuntimeClass()->className);
		if (entry.frame) m_topLevelClasses.insert(entry.frame->GetRuntimeClass()->className);
		entry.index = m_entries++;
		return true;
	}
}

std::string CRawlogReader::problemSummary() const
{
	std::string s;
	for (const auto& p : m_problems) s += (s.empty() ? "" : "\n") + p.message;
	return s;
}

size_t CRawlogReader::countEntries(const std::string& path)
{
	CRawlogReader reader(path);
	TRawlogEntry entry;
	try
	{
		while (reader.next(entry))
		{
		}
	}
	catch (const rawlog_error&)
	{
	}
	return reader.entriesRead();
}

}  // namespace hslam::io
