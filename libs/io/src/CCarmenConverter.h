/* hslam io (internal): second pass of the CARMEN import - turns the parsed
 * messages, in file order, into rawlog observations and reference poses. */
#pragma once

#include <hslam/common/tum_trajectory.h>
#include <hslam/io/CCarmenOdometryTracker.h>
#include <hslam/io/carmen_clock.h>
#include <hslam/io/carmen_import.h>
#include <hslam/io/carmen_log.h>
#include <hslam/io/carmen_range_limits.h>
#include <hslam/io/carmen_scan_geometry.h>

#include "carmen_rawlog_sink.h"

#include <string>
#include <vector>

namespace hslam::io
{
class CCarmenConverter
{
   public:
	CCarmenConverter(const TCarmenClock& clock, const TCarmenRangeLimits& limits, const TCarmenLaserMounts& mounts,
					 detail::CCarmenRawlogSink& sink);

	/** Handles one message (lasers and ODOM; PARAMs were read in the first pass). */
	void add(const TCarmenLogEntry& entry);

	const hslam::common::TTrajectory2D& reference() const { return m_reference; }
	size_t scansWritten() const { return m_front + m_rear + m_raw; }

	/** Copies counts and warnings into `report`. */
	void fillReport(TCarmenImportReport& report) const;

   private:
	void addLaser(const TCarmenLaser& laser, size_t line);
	void addFrontScan(const TCarmenLaser& laser, size_t line, double t_s);
	void writeOdometryOrGap(const TCarmenOdometryStep& step, size_t line, double t_s);
	void writeScan(const TCarmenLaser& laser, double t_s);
	void warnOnce(const std::string& warning);

	const TCarmenClock& m_clock;
	const TCarmenRangeLimits& m_limits;
	TCarmenLaserMounts m_mounts;
	detail::CCarmenRawlogSink& m_sink;
	CCarmenOdometryTracker m_tracker;
	hslam::common::TTrajectory2D m_reference;
	size_t m_scanIndex = 0;  //!< index into m_clock.t_s
	size_t m_front = 0, m_rear = 0, m_raw = 0, m_odometry = 0, m_gaps = 0;
	size_t m_previousFrontLine = 0;
	std::vector<std::string> m_warnings;
};

}  // namespace hslam::io
