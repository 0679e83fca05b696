/* hslam-grabber: time-ordered writing of the observations of all sensor
 * threads into one rawlog.
 *
 * Sensors deliver out of order across threads; observations are held for
 * hold_s in a time-sorted buffer and written once older than that (MRPT's
 * rawlog-grabber instead writes only the older half of its buffer each period
 * and at exit, losing the newest observations). finish() writes everything
 * left. In sensory-frame mode the stream goes through CSensoryFrameBuilder.
 * Optionally every written entry also feeds the mapping pipeline (live map). */
#pragma once

#include <hslam/hwdrivers/CRawlogRecorder.h>
#include <hslam/hwdrivers/CSensoryFrameBuilder.h>
#include <hslam/slam/CMappingPipeline.h>
#include <mrpt/hwdrivers/CGenericSensor.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

class CRecordingWriter
{
   public:
	struct TLabelStats
	{
		uint64_t count = 0;
		double first_s = 0, last_s = 0;
		uint64_t nonIncreasing = 0;  //!< timestamps not after the previous one of the same label
	};

	CRecordingWriter(const std::string& path, int compressLevel, bool sensoryFrames, double sfMaxSpan_s, double hold_s);

	/** Live mapping: every written entry is also given to this pipeline. */
	void setPipeline(hslam::slam::CMappingPipeline* pipeline) { m_pipeline = pipeline; }

	/** Thread-safe: called by the sensor threads. */
	void add(mrpt::hwdrivers::CGenericSensor::TListObservations&& obs);

	/** Writes what is older than hold_s and flushes the file. */
	void writeDue();
	/** Writes everything (call after all sensor threads stopped) and closes. */
	void finish();

	uint64_t objectsWritten() const { return m_rec.objectsWritten(); }
	uint64_t observationsWritten() const { return m_observations; }
	const std::map<std::string, TLabelStats>& labelStats() const { return m_stats; }

   private:
	void writeUpTo(mrpt::Clock::time_point limit);
	void writeObservation(const mrpt::obs::CObservation::Ptr& obs);
	void writePairs(const std::vector<hslam::hwdrivers::CSensoryFrameBuilder::TPair>& pairs);

	hslam::hwdrivers::CRawlogRecorder m_rec;
	bool m_sf;
	double m_hold_s;
	hslam::hwdrivers::CSensoryFrameBuilder m_builder;
	hslam::slam::CMappingPipeline* m_pipeline = nullptr;
	std::mutex m_mtx;
	std::multimap<mrpt::Clock::time_point, mrpt::obs::CObservation::Ptr> m_buffer;
	std::map<std::string, TLabelStats> m_stats;
	uint64_t m_observations = 0, m_entries = 0;
};
