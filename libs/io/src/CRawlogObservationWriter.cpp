/* hslam: CRawlogObservationWriter, observations-only gz rawlog output. */
#include <hslam/io/CRawlogObservationWriter.h>

#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace hslam::io
{
CRawlogObservationWriter::CRawlogObservationWriter(const std::string& path) : m_path(path)
{
	std::string error;
	if (!m_out.open(path, 1 /* fast compression */, error))
		throw std::runtime_error(path + ": cannot open for writing (" + error + ")");
}

CRawlogObservationWriter::~CRawlogObservationWriter()
{
	try
	{
		close();
	}
	catch (...)
	{
		// A destructor must not throw; close() is called explicitly on the normal path.
	}
}

void CRawlogObservationWriter::write(const mrpt::obs::CObservation& observation)
{
	if (!m_out.fileOpenCorrectly()) throw std::runtime_error(m_path + ": write after close");
	try
	{
		auto archive = mrpt::serialization::archiveFrom(m_out);
		archive << observation;
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(m_path + ": write failed after " + std::to_string(m_written) +
								 " observations: " + e.what());
	}
	++m_written;
	++m_perLabel[observation.sensorLabel];
}

void CRawlogObservationWriter::close()
{
	if (m_out.fileOpenCorrectly()) m_out.close();
}

}  // namespace hslam::io
