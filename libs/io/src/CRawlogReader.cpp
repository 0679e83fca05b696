#include <hslam/io/CRawlogReader.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

namespace hslam::io
{
CRawlogReader::CRawlogReader(const std::string& path) : m_path(path)
{
	if (!std::filesystem::is_regular_file(path)) throw rawlog_error(path + ": rawlog file not found");
	if (!m_file.open(path)) throw rawlog_error(path + ": cannot open rawlog file");
	m_archive = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZInputStream>>(m_file);
}

mrpt::serialization::CSerializable::Ptr CRawlogReader::readObject(bool endAllowed)
{
	const uint64_t positionBefore = m_file.getPosition();
	try
	{
		return m_archive->ReadObject();
	}
	catch (const mrpt::serialization::CExceptionEOF&)
	{
		// EOF before the first byte of an object is the normal end of file.
		if (endAllowed && m_file.getPosition() == positionBefore) return nullptr;
		throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) +
						   ": file is truncated (ends inside an object)");
	}
	catch (const std::exception& e)
	{
		std::string what = e.what();
		if (what.size() > 300) what = what.substr(0, 300) + "...";
		throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) + ": corrupt data: " + what);
	}
}

bool CRawlogReader::next(TRawlogEntry& entry)
{
	entry = TRawlogEntry();
	for (;;)
	{
		auto object = readObject(true);
		if (!object) return false;
		if (auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object))
			entry.observation = obs;
		else if (auto frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(object))
			entry.frame = frame;
		else if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(object))
		{
			entry.actions = actions;
			entry.frame = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(readObject(false));
			if (!entry.frame)
				throw rawlog_error(m_path + ": entry " + std::to_string(m_entries) +
								   ": an action collection is not followed by a sensory frame");
		}
		else
		{
			++m_skipped;
			continue;
		}
		entry.index = m_entries++;
		return true;
	}
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
