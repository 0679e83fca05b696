/* hslam: CRawlogFramesWriter, actions + sensory-frames gz rawlog output. */
#include <hslam/io/CRawlogFramesWriter.h>

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

namespace hslam::io
{
CRawlogFramesWriter::CRawlogFramesWriter(const std::string& path, const TMotionModelOptions& motionModel)
	: m_path(path), m_motionModel(motionModel)
{
	std::string error;
	if (!m_out.open(path, 1 /* fast compression */, error))
		throw std::runtime_error(path + ": cannot open for writing (" + error + ")");
}

CRawlogFramesWriter::~CRawlogFramesWriter()
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

void CRawlogFramesWriter::beginFrame(const std::optional<mrpt::poses::CPose2D>& increment, mrpt::Clock::time_point t)
{
	if (m_frameOpen) writePending();
	m_frameOpen = true;
	m_increment = increment;
	m_time = t;
}

void CRawlogFramesWriter::add(const mrpt::obs::CObservation::Ptr& observation)
{
	if (!m_out.fileOpenCorrectly()) throw std::runtime_error(m_path + ": write after close");
	m_pending.insert(observation);
}

void CRawlogFramesWriter::writePending()
{
	if (!m_out.fileOpenCorrectly()) throw std::runtime_error(m_path + ": write after close");
	mrpt::obs::CActionCollection actions;
	if (m_increment)
	{
		mrpt::obs::CActionRobotMovement2D move;
		move.computeFromOdometry(*m_increment, m_motionModel);  // MRPT builds the pose PDF
		move.timestamp = m_time;
		actions.insert(move);
		++m_actions;
	}
	try
	{
		auto archive = mrpt::serialization::archiveFrom(m_out);
		archive << actions << m_pending;
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(m_path + ": write failed after " + std::to_string(m_frames) + " frames: " + e.what());
	}
	++m_frames;
	m_pending.clear();
	m_frameOpen = false;
}

void CRawlogFramesWriter::close()
{
	if (!m_out.fileOpenCorrectly()) return;
	if (m_frameOpen || m_pending.size() > 0) writePending();
	m_out.close();
}

}  // namespace hslam::io
