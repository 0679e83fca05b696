/* hslam-grabber: rawlog writing (see CRecordingWriter.h). */
#include "CRecordingWriter.h"

#include <mrpt/system/datetime.h>

#include <vector>

CRecordingWriter::CRecordingWriter(const std::string& path, int compressLevel, bool sensoryFrames, double sfMaxSpan_s,
								   double hold_s)
	: m_rec(path, compressLevel), m_sf(sensoryFrames), m_hold_s(hold_s), m_builder(sfMaxSpan_s)
{
}

void CRecordingWriter::add(mrpt::hwdrivers::CGenericSensor::TListObservations&& obs)
{
	std::lock_guard<std::mutex> lk(m_mtx);
	for (auto& [t, o] : obs)
		if (auto ob = std::dynamic_pointer_cast<mrpt::obs::CObservation>(o)) m_buffer.emplace(ob->timestamp, ob);
}

void CRecordingWriter::writeObservation(const mrpt::obs::CObservation::Ptr& obs)
{
	auto& st = m_stats[obs->sensorLabel];
	const double t = mrpt::Clock::toDouble(obs->timestamp);
	if (st.count == 0)
		st.first_s = t;
	else if (t <= st.last_s)
		++st.nonIncreasing;
	st.last_s = t;
	++st.count;
	++m_observations;

	if (!m_sf)
	{
		m_rec.write(*obs);
		if (m_pipeline)
		{
			hslam::io::TRawlogEntry e;
			e.observation = obs;
			e.index = m_entries++;
			m_pipeline->processEntry(e);
		}
		return;
	}
	std::vector<hslam::hwdrivers::CSensoryFrameBuilder::TPair> pairs;
	m_builder.add(obs, pairs);
	writePairs(pairs);
}

void CRecordingWriter::writePairs(const std::vector<hslam::hwdrivers::CSensoryFrameBuilder::TPair>& pairs)
{
	for (const auto& [acts, sf] : pairs)
	{
		m_rec.write(*acts);
		m_rec.write(*sf);
		if (m_pipeline)
		{
			hslam::io::TRawlogEntry e;
			e.actions = acts;
			e.frame = sf;
			e.index = m_entries++;
			m_pipeline->processEntry(e);
		}
	}
}

void CRecordingWriter::writeUpTo(mrpt::Clock::time_point limit)
{
	std::vector<mrpt::obs::CObservation::Ptr> due;
	{
		std::lock_guard<std::mutex> lk(m_mtx);
		auto end = m_buffer.upper_bound(limit);
		for (auto it = m_buffer.begin(); it != end; ++it) due.push_back(it->second);
		m_buffer.erase(m_buffer.begin(), end);
	}
	for (const auto& o : due) writeObservation(o);
}

void CRecordingWriter::writeDue()
{
	writeUpTo(mrpt::Clock::now() - std::chrono::duration_cast<mrpt::Clock::duration>(std::chrono::duration<double>(m_hold_s)));
	m_rec.flush();
}

void CRecordingWriter::finish()
{
	writeUpTo(mrpt::Clock::time_point::max());
	if (m_sf)
	{
		std::vector<hslam::hwdrivers::CSensoryFrameBuilder::TPair> pairs;
		m_builder.flush(pairs);
		writePairs(pairs);
	}
	m_rec.close();
}
