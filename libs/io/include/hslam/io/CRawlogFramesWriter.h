/* hslam: incremental writer of an actions + sensory-frames MRPT rawlog
 * (gz-compressed; CActionCollection, CSensoryFrame, CActionCollection, ...),
 * the format MRPT's rbpf-slam and pf-localization read.
 *
 * Each frame starts with beginFrame(): its action is the odometry increment
 * since the previous frame as a CActionRobotMovement2D built by MRPT itself
 * (computeFromOdometry with MRPT's motion-model options), or an EMPTY action
 * collection when the increment is unknown (an odometry gap: "no odometry",
 * never zero motion, never the difference across the gap). Observations added
 * before the first frame go into the first frame's sensory frame. */
#pragma once

#include <mrpt/core/Clock.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cstddef>
#include <optional>
#include <string>

namespace hslam::io
{
class CRawlogFramesWriter
{
   public:
	using TMotionModelOptions = mrpt::obs::CActionRobotMovement2D::TMotionModelOptions;

	/** Opens (truncates) `path`; throws std::runtime_error naming it on failure.
	 * `motionModel`: MRPT's own defaults unless given. */
	explicit CRawlogFramesWriter(const std::string& path, const TMotionModelOptions& motionModel = {});
	/** Writes the pending frame and closes the file (never throws). */
	~CRawlogFramesWriter();
	CRawlogFramesWriter(const CRawlogFramesWriter&) = delete;
	CRawlogFramesWriter& operator=(const CRawlogFramesWriter&) = delete;

	/** Writes the pending frame (if any) and starts a new one whose action is
	 * `increment` (robot frame of the previous frame), or empty if unknown. */
	void beginFrame(const std::optional<mrpt::poses::CPose2D>& increment, mrpt::Clock::time_point t);

	/** Adds an observation to the current frame's sensory frame. */
	void add(const mrpt::obs::CObservation::Ptr& observation);

	/** Writes the pending frame, flushes and closes; safe to call twice. */
	void close();

	size_t framesWritten() const { return m_frames; }
	size_t actionsWritten() const { return m_actions; }

   private:
	void writePending();

	std::string m_path;
	TMotionModelOptions m_motionModel;
	mrpt::io::CFileGZOutputStream m_out;
	bool m_frameOpen = false;
	std::optional<mrpt::poses::CPose2D> m_increment;
	mrpt::Clock::time_point m_time;
	mrpt::obs::CSensoryFrame m_pending;
	size_t m_frames = 0, m_actions = 0;
};

}  // namespace hslam::io
