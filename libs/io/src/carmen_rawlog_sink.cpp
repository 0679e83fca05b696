/* hslam io (internal): the two rawlog formats of the CARMEN importer. */
#include "carmen_rawlog_sink.h"

#include <hslam/io/carmen_observations.h>

#include <stdexcept>

namespace hslam::io::detail
{
namespace
{
/** Observations only: an ODOMETRY observation (our absolute chain) or the gap comment. */
class CObservationsSink : public CCarmenRawlogSink
{
   public:
	explicit CObservationsSink(const std::string& path) : m_writer(path) {}
	void write(const mrpt::obs::CObservation::Ptr& observation) override { m_writer.write(*observation); }
	void odometry(const TCarmenOdometryStep& step, double t_s) override
	{
		m_writer.write(*makeCarmenOdometry(step, t_s));
	}
	void gap(const mrpt::obs::CObservationComment::Ptr& marker) override { m_writer.write(*marker); }
	void close() override { m_writer.close(); }

   private:
	CRawlogObservationWriter m_writer;
};

/** Actions + sensory frames: one frame per front scan; its action is the raw
 * increment since the previous front scan (identity for the first), or no
 * action at a gap, whose sensory frame also holds the gap comment. */
class CFramesSink : public CCarmenRawlogSink
{
   public:
	explicit CFramesSink(const std::string& path) : m_writer(path) {}
	void write(const mrpt::obs::CObservation::Ptr& observation) override { m_writer.add(observation); }
	void odometry(const TCarmenOdometryStep& step, double t_s) override
	{
		m_writer.beginFrame(step.first ? mrpt::poses::CPose2D() : step.increment, mrpt::Clock::fromDouble(t_s));
	}
	void gap(const mrpt::obs::CObservationComment::Ptr& marker) override
	{
		m_writer.beginFrame(std::nullopt, marker->timestamp);
		m_writer.add(marker);
	}
	void close() override { m_writer.close(); }

   private:
	CRawlogFramesWriter m_writer;
};
}  // namespace

std::unique_ptr<CCarmenRawlogSink> makeCarmenRawlogSink(const std::string& format, const std::string& path)
{
	if (format == "observations") return std::make_unique<CObservationsSink>(path);
	if (format == "frames") return std::make_unique<CFramesSink>(path);
	throw std::invalid_argument("carmen_import: unknown rawlog format '" + format + "' (observations|frames)");
}

}  // namespace hslam::io::detail
