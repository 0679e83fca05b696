/* hslam: groups a time-ordered observation stream into the Actions/SensoryFrame
 * rawlog format (use_sensoryframes = 1), with correct odometry increments.
 *
 * MRPT 2.5's rawlog-grabber converts CObservationOdometry into
 * CActionRobotMovement2D using function-static state, and takes the 2nd
 * reading's increment w.r.t. (0,0,0) instead of the 1st reading
 * (../shared/notes/mrpt-plugins-and-protocols.md s.1.4). Here, per odometry
 * label, increment_k = odo_{k-1} (-) odo_k (inverse pose composition), and
 * the increments that happen before a frame's first observation are composed
 * into that frame's action: "the robot moved by the action, then sensed the
 * frame". A frame is closed when a sensor label repeats in it or its time span
 * would exceed max_time_span_s. The first frame's action is the identity. */
#pragma once

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hslam::hwdrivers
{
class CSensoryFrameBuilder
{
   public:
	using TPair = std::pair<mrpt::obs::CActionCollection::Ptr, mrpt::obs::CSensoryFrame::Ptr>;

	explicit CSensoryFrameBuilder(double maxTimeSpan_s = 0.25) : m_maxSpan_s(maxTimeSpan_s) {}

	/** Motion model of the emitted CActionRobotMovement2D. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel;

	/** Adds the next observation (timestamps non-decreasing); appends completed pairs. */
	void add(const mrpt::obs::CObservation::Ptr& obs, std::vector<TPair>& out);
	/** Emits the open frame, if any. */
	void flush(std::vector<TPair>& out);

   private:
	double m_maxSpan_s;
	std::map<std::string, mrpt::poses::CPose2D> m_lastOdo;  //!< per odometry label
	mrpt::poses::CPose2D m_pending;  //!< motion since the open frame started
	bool m_pendingValid = false;
	mrpt::poses::CPose2D m_frameAction;
	bool m_frameActionValid = false;
	mrpt::Clock::time_point m_frameActionTime{};
	mrpt::obs::CSensoryFrame::Ptr m_frame;
	std::set<std::string> m_frameLabels;
	mrpt::Clock::time_point m_frameStart{}, m_lastOdoTime{};
};

}  // namespace hslam::hwdrivers
